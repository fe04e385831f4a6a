#include "libassess/CampaignRunner.hpp"

#include <functional>
#include <limits>
#include <mutex>
#include <optional>

#include "CampaignDispatcher.hpp"
#include "CampaignJob.hpp"
#include "JobRunner.hpp"
#include "RankExchange.hpp"
#include "libassess/ForestSummary.hpp"
#include "libassess/MpiWorld.hpp"
#include "libstand/ForestGenerator.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

namespace {

constexpr double kUnforestedRunM = 30;  // Sect. 2.3.2: the blocks reach ~15 m/s before the forest

using Exchange = std::function<std::optional<CampaignJob>(std::optional<JobOutcome> finished)>;

}  // namespace

stand::Window forestExtent(const dem::Scene& bareScene) {
    const auto& soil = bareScene.soil();
    const double x0 = bareScene.config().release.x + kUnforestedRunM;
    if (!(x0 < soil.xmax()))
        throw InputError(bareScene.config().sourceFile, 0,
                         "no room for a forest: it starts 30 m down-slope of the release (x = " + std::to_string(x0) +
                             " m) but the terrain ends at x = " + std::to_string(soil.xmax()) + " m");
    return stand::Window::rectangle(x0, soil.ymin(), soil.xmax(), soil.ymax());
}

void runMissing(const std::vector<Campaign>& plan, CampaignStore& store, std::shared_ptr<const dem::Scene> bareScene,
                const std::vector<stand::StandCatalogue>& catalogues, const RunnerSettings& settings) {
    for (std::size_t c = 0; c < plan.size(); ++c) {
        if (!plan[c].forested || !store.missingRuns(c).empty() || store.forest(c)) continue;
        // All runs are stored but the forest's statistics were damaged or edited: only they are
        // computed again (the forest is its seed's).
        const stand::Window extent = forestExtent(*bareScene);
        store.saveForest(c, summariseForest(campaignForest(plan[c], catalogues.at(plan[c].stand), extent), extent));
    }
    CampaignDispatcher dispatcher(plan, store, settings);
    JobRunner runner(plan, bareScene, catalogues);
    const int threads = threadsFor(settings.threads, dispatcher.runsToDo());
    const std::function<JobOutcome(const CampaignJob&)> run = [&](const CampaignJob& job) { return runner.run(job); };
    const Exchange own = [&](std::optional<JobOutcome> finished) { return dispatcher.exchange(0, std::move(finished)); };
    const AnswerRank answer = [&](int rank, std::optional<std::string> finished) -> std::optional<std::string> {
        const std::optional<CampaignJob> job =
            dispatcher.exchange(rank, finished ? std::optional<JobOutcome>(decodeOutcome(*finished)) : std::nullopt);
        if (!job) return std::nullopt;
        return encode(*job);
    };
    coordinateRanks(MpiWorld::current(), [&] { workOnThreads(threads, own, run); }, answer,
                    [&](std::exception_ptr e) { dispatcher.fail(e); });
    dispatcher.rethrowFailure();
}

void serveCampaigns(const std::vector<Campaign>& plan, std::shared_ptr<const dem::Scene> bareScene,
                    const std::vector<stand::StandCatalogue>& catalogues, const RunnerSettings& settings) {
    JobRunner runner(plan, bareScene, catalogues);
    CoordinatorLink link(MpiWorld::current());
    const Exchange remote = [&](std::optional<JobOutcome> finished) -> std::optional<CampaignJob> {
        const std::optional<std::string> job = link.exchange(finished ? std::optional<std::string>(encode(*finished)) : std::nullopt);
        if (!job) return std::nullopt;
        return decodeJob(*job);
    };
    const std::function<JobOutcome(const CampaignJob&)> run = [&](const CampaignJob& job) { return runner.run(job); };
    workOnThreads(threadsFor(settings.threads, std::numeric_limits<int>::max()), remote, run);
    link.done();
}

}  // namespace sylva::assess
