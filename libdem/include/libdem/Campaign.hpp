#pragma once
// Many runs of one scene, spread over threads. Run i's random draws come from a seed derived from
// (campaign seed, i) alone, so results do not depend on the number of threads or their timing.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "libdem/BlockRun.hpp"

namespace sylva::dem {

// splitmix64's finaliser: spreads every input bit over the output, so neighbouring inputs give
// unrelated outputs (used to derive seeds).
std::uint64_t splitmix64(std::uint64_t x);

std::uint64_t runSeed(std::uint64_t campaignSeed, int run);

// The DEM of the paper's Sect. 2.1-2.2, or its lumped-mass model of Sect. 2.3.1 (LumpedRun).
enum class Model { Dem, Lumped };
Model parseModel(const std::string& name);  // "dem" | "lumped"; InputError otherwise
std::string toString(Model m);

struct CampaignOptions {
    Model model = Model::Dem;
    int runs = 100;
    // If not empty, run only these run indices (each still seeded from (seed, index)), e.g. the
    // runs an interrupted campaign had not finished; results come back in this order.
    std::vector<int> only;
    std::uint64_t seed = 1;
    int threads = 0;  // 0: all cores
    RunOptions run;
    // Called after each finished run (from the worker threads, serialised), e.g. for a progress bar.
    std::function<void(const RunResult&, int done, int total)> onRunDone;
};

// Results in run order (or in the order of `only`). A run that fails numerically (SimulationError)
// is kept as StopReason::Failed with its message (failedRun) and the others go on; any other error
// (a bad release: InputError) stops the campaign, prefixed by the run's index and seed.
std::vector<RunResult> runCampaign(const Scene& scene, const CampaignOptions& options);

}  // namespace sylva::dem
