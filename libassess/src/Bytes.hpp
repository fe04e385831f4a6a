#pragma once
// Values as the bytes of a message between MPI ranks, and back. Every rank runs the same executable
// on the same kind of machine, so a value travels in its own layout. Reading past a message's end, or
// leaving bytes unread (end()), throws.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace sylva::assess {

class ByteWriter {
public:
    template <class T>
    ByteWriter& put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
        return *this;
    }
    ByteWriter& put(const std::string& s) {
        put(static_cast<std::uint64_t>(s.size()));
        bytes_ += s;
        return *this;
    }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

class ByteReader {
public:
    explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        std::memcpy(&v, take(sizeof v), sizeof v);
        return v;
    }
    std::string getString() {
        const std::size_t n = count(1);
        return std::string(take(n), n);
    }
    // A count of items of `bytesEach` bytes that follow, checked against what is left (a garbled count
    // must not make the reader allocate what it cannot read).
    std::size_t count(std::size_t bytesEach) {
        const auto n = get<std::uint64_t>();
        if (n > (bytes_.size() - at_) / bytesEach) throw std::runtime_error("MPI message: a count runs past its end");
        return static_cast<std::size_t>(n);
    }
    void end() const {
        if (at_ != bytes_.size()) throw std::runtime_error("MPI message: " + std::to_string(bytes_.size() - at_) + " bytes too many");
    }

private:
    const char* take(std::size_t n) {
        if (n > bytes_.size() - at_) throw std::runtime_error("MPI message cut short");
        const char* p = bytes_.data() + at_;
        at_ += n;
        return p;
    }
    const std::string& bytes_;
    std::size_t at_ = 0;
};

}  // namespace sylva::assess
