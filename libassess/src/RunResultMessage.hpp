#pragma once
// A block run's whole result (dem::RunResult: its values, impacts, ledgers, trajectory) in an MPI
// message, so that `simulate` on several ranks writes what one process writes.
#include "Bytes.hpp"
#include "libdem/BlockRun.hpp"

namespace sylva::assess {

void put(ByteWriter& w, const dem::RunResult& r);
dem::RunResult getRunResult(ByteReader& r);

}  // namespace sylva::assess
