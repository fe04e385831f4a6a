#include "CampaignJob.hpp"

#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace sylva::assess {

namespace {

class Writer {
public:
    template <class T>
    Writer& put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
        return *this;
    }
    Writer& put(const std::string& s) {
        put(static_cast<std::uint64_t>(s.size()));
        bytes_ += s;
        return *this;
    }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

class Reader {
public:
    explicit Reader(const std::string& bytes) : bytes_(bytes) {}
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        std::memcpy(&v, take(sizeof v), sizeof v);
        return v;
    }
    std::string getString() {
        const auto n = static_cast<std::size_t>(get<std::uint64_t>());
        return std::string(take(n), n);
    }
    void end() const {
        if (at_ != bytes_.size()) throw std::runtime_error("campaign message: " + std::to_string(bytes_.size() - at_) + " bytes too many");
    }

private:
    const char* take(std::size_t n) {
        if (n > bytes_.size() - at_) throw std::runtime_error("campaign message cut short");
        const char* p = bytes_.data() + at_;
        at_ += n;
        return p;
    }
    const std::string& bytes_;
    std::size_t at_ = 0;
};

void putJob(Writer& w, const CampaignJob& j) { w.put(static_cast<std::uint64_t>(j.campaign)).put(j.run).put(j.summarise); }

CampaignJob getJob(Reader& r) {
    CampaignJob j;
    j.campaign = static_cast<std::size_t>(r.get<std::uint64_t>());
    j.run = r.get<int>();
    j.summarise = r.get<bool>();
    return j;
}

}  // namespace

std::string encode(const CampaignJob& job) {
    Writer w;
    putJob(w, job);
    return w.take();
}

CampaignJob decodeJob(const std::string& bytes) {
    Reader r(bytes);
    const CampaignJob j = getJob(r);
    r.end();
    return j;
}

std::string encode(const JobOutcome& o) {
    static_assert(std::is_trivially_copyable_v<ForestSummary>);
    Writer w;
    putJob(w, o.job);
    w.put(o.record).put(o.failure).put(o.forest.has_value());
    if (o.forest) w.put(*o.forest);
    w.put(o.error).put(o.inputError);
    return w.take();
}

JobOutcome decodeOutcome(const std::string& bytes) {
    Reader r(bytes);
    JobOutcome o;
    o.job = getJob(r);
    o.record = r.getString();
    o.failure = r.getString();
    if (r.get<bool>()) o.forest = r.get<ForestSummary>();
    o.error = r.getString();
    o.inputError = r.get<bool>();
    r.end();
    return o;
}

}  // namespace sylva::assess
