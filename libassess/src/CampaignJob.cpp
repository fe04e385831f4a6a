#include "CampaignJob.hpp"

#include <type_traits>

#include "Bytes.hpp"

namespace sylva::assess {

namespace {

void putJob(ByteWriter& w, const CampaignJob& j) { w.put(static_cast<std::uint64_t>(j.campaign)).put(j.run).put(j.summarise); }

CampaignJob getJob(ByteReader& r) {
    CampaignJob j;
    j.campaign = static_cast<std::size_t>(r.get<std::uint64_t>());
    j.run = r.get<int>();
    j.summarise = r.get<bool>();
    return j;
}

}  // namespace

std::string encode(const CampaignJob& job) {
    ByteWriter w;
    putJob(w, job);
    return w.take();
}

CampaignJob decodeJob(const std::string& bytes) {
    ByteReader r(bytes);
    const CampaignJob j = getJob(r);
    r.end();
    return j;
}

std::string encode(const JobOutcome& o) {
    static_assert(std::is_trivially_copyable_v<ForestSummary>);
    ByteWriter w;
    putJob(w, o.job);
    w.put(o.record).put(o.failure).put(o.forest.has_value());
    if (o.forest) w.put(*o.forest);
    w.put(o.error).put(o.inputError);
    return w.take();
}

JobOutcome decodeOutcome(const std::string& bytes) {
    ByteReader r(bytes);
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
