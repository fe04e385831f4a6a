#pragma once
// Runs what an assessment still lacks: every missing run of every campaign, as one queue of
// (campaign, run) jobs shared by all threads, so the cores stay busy across campaign boundaries instead
// of idling at each campaign's tail. A campaign's forest is generated and its scene built by the first
// thread that needs it, and released after its last run. Each run is seeded from (campaign seed, run)
// alone (dem::runCampaign), so results do not depend on the threads or the order.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "libassess/CampaignPlan.hpp"
#include "libassess/CampaignStore.hpp"
#include "libdem/BlockRun.hpp"
#include "libdem/Scene.hpp"
#include "libstand/StandCatalogue.hpp"

namespace sylva::assess {

struct RunnerSettings {
    int threads = 0;  // 0: all cores
    // After each finished run (serialised): the campaign's id, runs done and runs to do in this call.
    std::function<void(const std::string& campaign, int done, int total)> onRunDone;
    // A run that stopped on a numerical error (stored as failed, left out of the analysis).
    std::function<void(const std::string& campaign, const dem::RunResult& run)> onRunFailed;
};

// The part of the slope the forests cover (Sect. 2.3.2): from 30 m down-slope of the release point to
// the end of the terrain, across its whole width. Throws InputError if nothing is left for a forest.
stand::Window forestExtent(const dem::Scene& bareScene);

// Generates each campaign's forest when runs are missing or its statistics are not stored, writes the
// statistics, runs the missing runs and appends each to its log as it finishes. `bareScene` is the
// scene without forest (the baseline's; forests are placed in copies of its configuration),
// `catalogues` one per stand of the design. A failing run stops the queue; the error names the
// campaign, the run and its seed; what finished is kept for --resume.
void runMissing(const std::vector<Campaign>& plan, CampaignStore& store, std::shared_ptr<const dem::Scene> bareScene,
                const std::vector<stand::StandCatalogue>& catalogues, const RunnerSettings& settings);

}  // namespace sylva::assess
