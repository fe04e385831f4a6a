#pragma once
// Runs what an assessment still lacks: every missing run of every campaign, handed out run by run to
// the threads of this process and, under mpirun, to the threads of every rank, so the cores stay busy
// across campaign boundaries instead of idling at each campaign's tail. Rank 0 coordinates and is the
// only writer of the store; the other ranks run jobs and send their results back (serveCampaigns).
// Each run is seeded from (campaign seed, run) alone (dem::runCampaign), so results do not depend on
// the ranks, the threads or the order.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "libassess/CampaignPlan.hpp"
#include "libassess/CampaignStore.hpp"
#include "libassess/RunRecord.hpp"
#include "libdem/BlockRun.hpp"
#include "libdem/Scene.hpp"
#include "libstand/StandCatalogue.hpp"

namespace sylva::assess {

struct RunnerSettings {
    int threads = 0;  // 0: all cores
    // After each finished run (serialised): the campaign's id, runs done and runs to do in this call.
    std::function<void(const std::string& campaign, int done, int total)> onRunDone;
    // A run that stopped on a numerical error (stored as failed, left out of the analysis): why.
    std::function<void(const std::string& campaign, const RunRecord& run, const std::string& failure)> onRunFailed;
};

// The part of the slope the forests cover (Sect. 2.3.2): from 30 m down-slope of the release point to
// the end of the terrain, across its whole width. Throws InputError if nothing is left for a forest.
stand::Window forestExtent(const dem::Scene& bareScene);

// On rank 0 (or the one process): generates each campaign's forest when runs are missing or its
// statistics are not stored, writes the statistics, runs the missing runs and appends each to its log
// as it finishes. `bareScene` is the scene without forest (the baseline's; forests are placed in
// copies of its configuration), `catalogues` one per stand of the design. A run that cannot be run
// stops the queue; the error names the campaign, the run and its seed; what finished is kept for
// --resume. Under mpirun, returns once every other rank has stopped.
void runMissing(const std::vector<Campaign>& plan, CampaignStore& store, std::shared_ptr<const dem::Scene> bareScene,
                const std::vector<stand::StandCatalogue>& catalogues, const RunnerSettings& settings);
// On the other ranks, at the same time: runs the jobs rank 0 hands out until it has none left (same
// plan, scene and catalogues as rank 0's; settings.threads threads; the callbacks are not called).
void serveCampaigns(const std::vector<Campaign>& plan, std::shared_ptr<const dem::Scene> bareScene,
                    const std::vector<stand::StandCatalogue>& catalogues, const RunnerSettings& settings);

}  // namespace sylva::assess
