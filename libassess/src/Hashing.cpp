#include "libassess/Hashing.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>

#include "libstand/InputError.hpp"

namespace sylva::assess {

namespace {
// splitmix64's finaliser: spreads every input bit over the output, so seeds 1 and 2 do not give
// neighbouring derived seeds.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}
}  // namespace

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
    return static_cast<std::uint32_t>(mix(mix(seed) ^ fnv1a64(label)) & 0xFFFFFFFFULL);
}

std::string toHex(std::uint64_t value, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%0*llx", digits, static_cast<unsigned long long>(value));
    return buf;
}

}  // namespace sylva::assess
