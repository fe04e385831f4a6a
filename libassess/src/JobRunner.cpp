#include "JobRunner.hpp"

#include <exception>

#include "libassess/CampaignRunner.hpp"
#include "libassess/RunRecord.hpp"
#include "libdem/Campaign.hpp"
#include "libstand/ForestGenerator.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

stand::Forest campaignForest(const Campaign& campaign, const stand::StandCatalogue& catalogue, const stand::Window& extent) {
    stand::GenerationSettings g;
    g.structure = campaign.structure;
    g.seed = campaign.forestSeed;
    return stand::generateForest(catalogue, extent, g).forest;
}

JobRunner::JobRunner(const std::vector<Campaign>& plan, std::shared_ptr<const dem::Scene> bareScene,
                     const std::vector<stand::StandCatalogue>& catalogues)
    : plan_(plan), bareScene_(std::move(bareScene)), catalogues_(catalogues), extent_(forestExtent(*bareScene_)) {}

std::shared_ptr<JobRunner::SceneSlot> JobRunner::slot(std::size_t campaign) {
    std::lock_guard<std::mutex> lock(mutex_);
    // Scenes no thread holds are dropped: a forested scene holds its own soil bed, and keeping all of
    // them would hold the whole design in memory.
    for (auto it = slots_.begin(); it != slots_.end();)
        it = it->first != campaign && it->second.use_count() == 1 ? slots_.erase(it) : std::next(it);
    auto& s = slots_[campaign];
    if (!s) s = std::make_shared<SceneSlot>();
    return s;
}

JobOutcome JobRunner::run(const CampaignJob& job) {
    JobOutcome outcome;
    outcome.job = job;
    try {
        const Campaign& campaign = plan_.at(job.campaign);
        std::shared_ptr<const dem::Scene> scene = bareScene_;
        const std::shared_ptr<SceneSlot> held = campaign.forested ? slot(job.campaign) : nullptr;
        if (held) {
            std::lock_guard<std::mutex> lock(held->mutex);
            if (!held->scene) {
                stand::Forest forest = campaignForest(campaign, catalogues_.at(campaign.stand), extent_);
                held->forest = summariseForest(forest, extent_);
                held->scene = std::make_shared<const dem::Scene>(bareScene_->config(), std::move(forest));
            }
            scene = held->scene;
            if (job.summarise) outcome.forest = held->forest;
        }
        dem::CampaignOptions options;
        options.model = campaign.model;
        options.only = {job.run};
        options.seed = campaign.runSeed;
        options.threads = 1;
        const dem::RunResult result = dem::runCampaign(*scene, options).front();
        outcome.record = formatRunLine(toRecord(result));
        if (result.reason == dem::StopReason::Failed) outcome.failure = result.failure;
    } catch (const std::exception& e) {
        outcome.error = e.what();
        outcome.inputError = dynamic_cast<const InputError*>(&e) != nullptr;
    }
    return outcome;
}

}  // namespace sylva::assess
