#pragma once
// Runs campaign jobs in one process, on any of its threads. A campaign's scene (its forest generated
// from the campaign's seed, and the soil bed) is built by the first thread that needs it and kept
// while a thread of this process uses it: with the dispatcher keeping each team on one campaign,
// a process holds about one forested scene per thread.
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "CampaignJob.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libdem/Scene.hpp"
#include "libstand/StandCatalogue.hpp"
#include "libstand/Window.hpp"

namespace sylva::assess {

// The campaign's virtual forest over `extent`: its seed's, whichever process generates it.
stand::Forest campaignForest(const Campaign& campaign, const stand::StandCatalogue& catalogue, const stand::Window& extent);

class JobRunner {
public:
    JobRunner(const std::vector<Campaign>& plan, std::shared_ptr<const dem::Scene> bareScene,
              const std::vector<stand::StandCatalogue>& catalogues);
    // Never throws: an error becomes the outcome's `error`.
    JobOutcome run(const CampaignJob& job);

private:
    struct SceneSlot {
        std::mutex mutex;  // held while the scene is built
        std::shared_ptr<const dem::Scene> scene;
        ForestSummary forest;  // of the generated forest, over the forest extent
    };
    std::shared_ptr<SceneSlot> slot(std::size_t campaign);

    const std::vector<Campaign>& plan_;
    std::shared_ptr<const dem::Scene> bareScene_;
    const std::vector<stand::StandCatalogue>& catalogues_;
    stand::Window extent_;
    std::mutex mutex_;
    std::map<std::size_t, std::shared_ptr<SceneSlot>> slots_;
};

}  // namespace sylva::assess
