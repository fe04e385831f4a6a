#pragma once
// One finished block run as an assessment keeps it: a row of the campaign store's runs table, and the
// line of text an MPI rank sends it as. Both carry a checksum of the values, so a row edited or
// damaged on disk, or a line garbled on its way, is recognised and the run redone.
#include <cstdint>
#include <optional>
#include <string>

#include "libdem/BlockRun.hpp"

namespace sylva::assess {

struct RunRecord {
    int run = 0;                 // index in its campaign; its seed is dem::runSeed(campaign seed, run)
    std::uint64_t seed = 0;
    double runoutM = 0;          // along the slope (Eq. 26's distances)
    double runoutHorizontalM = 0;
    double stopX = 0, stopY = 0, stopZ = 0;  // m
    double energyLineDeg = 0, maxSpeed = 0;
    long treeImpacts = 0;
    std::string reason;          // dem::toString(StopReason)
};

RunRecord toRecord(const dem::RunResult& result);

// FNV-1a of the record's values written at 17 significant digits (16 hexadecimal digits).
std::string runChecksum(const RunRecord& record);
// The record as one CSV line without its newline, ending with its checksum. Numbers are written
// with 17 significant digits, so they read back to the same doubles.
std::string formatRunLine(const RunRecord& record);
// The record of a line, or nothing if the line is malformed or its checksum does not match.
std::optional<RunRecord> parseRunLine(const std::string& line);

}  // namespace sylva::assess
