#include "libassess/Hashing.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "libdem/Campaign.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {


std::uint64_t fnv1a64(const std::string& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 0x100000001b3ULL;
    }
    return h;
}

std::uint64_t fileFingerprint(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, "cannot read the file");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return fnv1a64(bytes);
}

std::uint32_t derivedSeed(std::uint64_t seed, const std::string& label) {
    return static_cast<std::uint32_t>(dem::splitmix64(dem::splitmix64(seed) ^ fnv1a64(label)) & 0xFFFFFFFFULL);
}

std::string toHex(std::uint64_t value, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%0*llx", digits, static_cast<unsigned long long>(value));
    return buf;
}

std::string exactText(double v) {
    if (std::isnan(v)) return "nan";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

}  // namespace sylva::assess
