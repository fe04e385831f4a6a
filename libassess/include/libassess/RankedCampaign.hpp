#pragma once
// dem::runCampaign spread over the ranks mpirun started (a single process: runCampaign itself). The
// runs are handed out in small batches to every rank's threads as they free up, and gathered on rank
// 0 in run order; each run keeps its seed, so the results are bit for bit one process's.
#include <vector>

#include "libdem/Campaign.hpp"

namespace sylva::assess {

// On rank 0: every run's result in run order (as runCampaign); options.onRunDone is called there, as
// results arrive. On the other ranks: nothing (they only run). Every rank passes the same scene and
// options. Errors as runCampaign's, thrown on rank 0.
std::vector<dem::RunResult> runCampaignOnRanks(const dem::Scene& scene, const dem::CampaignOptions& options);

}  // namespace sylva::assess
