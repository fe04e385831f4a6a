#pragma once
// Fingerprints and derived seeds for an assessment campaign: a run line's checksum (to detect a line
// cut by a kill), an input file's fingerprint (to refuse resuming with other data) and the seed of
// each forest realisation and block campaign, derived from the user's seed and the campaign's name.
#include <cstdint>
#include <string>

namespace sylva::assess {

// FNV-1a, 64 bits: fast, stable across platforms, and enough to tell a damaged line from a good one.
std::uint64_t fnv1a64(const std::string& bytes);

// Fingerprint of a file's contents (fnv1a64 of its bytes); throws InputError if it cannot be read.
std::uint64_t fileFingerprint(const std::string& path);

// A seed for GSL's mt19937 (32 bits, so it means the same on every platform) derived from the
// campaign seed and a label such as "forest|GR1|A|3": different labels give unrelated seeds.
std::uint32_t derivedSeed(std::uint64_t seed, const std::string& label);

// A double as the text its checksum is taken over: 17 significant digits, which read back to the same
// double; every NaN is "nan" (the sign of a NaN is not kept by the store, nor meaningful).
std::string exactText(double value);

// Lower-case hexadecimal, zero-padded to `digits`.
std::string toHex(std::uint64_t value, int digits);

}  // namespace sylva::assess
