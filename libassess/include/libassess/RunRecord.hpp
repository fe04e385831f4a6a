#pragma once
// One finished block run as an assessment stores it: one line of a run log, ending with a checksum
// of the line so that a line cut short by a kill (or damaged on disk) is recognised and redone.
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

// The run log's header row (CSV column names, the last one being the checksum).
std::string runLogHeader();
// The record as one CSV line without its newline. Numbers are written with 17 significant digits,
// so they read back to the same doubles: a resumed campaign computes from the very same values.
std::string formatRunLine(const RunRecord& record);
// The record of a line, or nothing if the line is malformed or its checksum does not match.
std::optional<RunRecord> parseRunLine(const std::string& line);

}  // namespace sylva::assess
