#pragma once
// All a finished run of a hazard map leaves to its pass (its cells, deposit, crossings, path), and
// the bytes the map's store keeps it as (HazardStore), read back when a map is resumed.
#include <string>
#include <vector>

#include "libassess/BlockPaths.hpp"
#include "libassess/CheckLines.hpp"
#include "libassess/HazardMap.hpp"

namespace sylva::assess {

struct RunOutcome {
    bool failed = false;
    BlockTrace trace;
    std::size_t volumeClass = 0;
    std::vector<LineCrossing> crossings;
    BlockPath path;
    std::vector<ImpactPoint> impacts;
};

// In this machine's layout, as the MPI messages (Bytes.hpp); decode throws std::runtime_error on
// bytes that are not a whole record. `failed` is not in the bytes: the store keeps it in a column of
// its own, and a failed run has no record.
std::string encode(const RunOutcome& outcome);
RunOutcome decode(const std::string& bytes);

}  // namespace sylva::assess
