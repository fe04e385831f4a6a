#include "libassess/CampaignRunner.hpp"

#include <atomic>
#include <exception>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "libassess/ForestSummary.hpp"
#include "libdem/Campaign.hpp"
#include "libstand/ForestGenerator.hpp"
#include "libstand/InputError.hpp"

namespace sylva::assess {

namespace {

constexpr double kUnforestedRunM = 30;  // Sect. 2.3.2: the blocks reach ~15 m/s before the forest

// A campaign's scene, built on first use and dropped after the campaign's last run (a forested scene
// holds its own soil bed: keeping all of them would hold the whole design in memory).
struct SceneSlot {
    std::mutex mutex;
    std::shared_ptr<const dem::Scene> scene;
    int pending = 0;  // runs of this campaign not finished yet (guarded by mutex)
};

stand::Forest generate(const Campaign& c, const stand::StandCatalogue& catalogue, const stand::Window& extent) {
    stand::GenerationSettings g;
    g.structure = c.structure;
    g.seed = c.forestSeed;
    return stand::generateForest(catalogue, extent, g).forest;
}

std::shared_ptr<const dem::Scene> forestScene(const Campaign& c, CampaignStore& store, const dem::Scene& bare,
                                              const stand::StandCatalogue& catalogue) {
    const stand::Window extent = forestExtent(bare);
    stand::Forest forest = generate(c, catalogue, extent);
    writeForestSummary(store.forestSummaryPath(c), summariseForest(forest, extent));
    return std::make_shared<const dem::Scene>(bare.config(), std::move(forest));
}

// The error of a job, with the campaign it belongs to (runCampaign's message names the run and seed).
std::exception_ptr inCampaign(const Campaign& c, const std::exception& e) {
    const std::string what = "campaign " + c.id + ": " + e.what();
    if (dynamic_cast<const InputError*>(&e)) return std::make_exception_ptr(InputError(what));
    return std::make_exception_ptr(std::runtime_error(what));
}

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
    std::vector<SceneSlot> slots(plan.size());
    std::vector<std::pair<std::size_t, int>> jobs;
    for (std::size_t c = 0; c < plan.size(); ++c) {
        const auto missing = store.log(c).missingRuns();
        for (int run : missing) jobs.emplace_back(c, run);
        slots[c].pending = static_cast<int>(missing.size());
        if (!plan[c].forested) {
            slots[c].scene = bareScene;
        } else if (missing.empty() && !forestSummaryIntact(store.forestSummaryPath(plan[c]))) {
            // All runs are stored but the forest's statistics were lost, damaged or edited: only they
            // are computed again (the forest is its seed's).
            if (std::filesystem::exists(store.forestSummaryPath(plan[c])))
                store.note(store.forestSummaryPath(plan[c]) + ": checksum mismatch (edited or damaged): computed again");
            const stand::Window extent = forestExtent(*bareScene);
            writeForestSummary(store.forestSummaryPath(plan[c]),
                               summariseForest(generate(plan[c], catalogues.at(plan[c].stand), extent), extent));
        }
    }
    if (jobs.empty()) return;

    std::atomic<std::size_t> next{0};
    std::mutex storeMutex;
    std::exception_ptr failure;
    std::atomic<bool> stop{false};
    int done = 0;
    const int total = static_cast<int>(jobs.size());
    auto worker = [&] {
        while (!stop) {
            const std::size_t j = next.fetch_add(1);
            if (j >= jobs.size()) return;
            const auto [c, run] = jobs[j];
            const Campaign& campaign = plan[c];
            try {
                std::shared_ptr<const dem::Scene> scene;
                {
                    std::lock_guard<std::mutex> lock(slots[c].mutex);
                    if (!slots[c].scene) slots[c].scene = forestScene(campaign, store, *bareScene, catalogues.at(campaign.stand));
                    scene = slots[c].scene;
                }
                dem::CampaignOptions options;
                options.only = {run};
                options.seed = campaign.runSeed;
                options.threads = 1;
                const dem::RunResult result = dem::runCampaign(*scene, options).front();
                const RunRecord record = toRecord(result);
                {
                    std::lock_guard<std::mutex> lock(storeMutex);
                    if (result.reason == dem::StopReason::Failed && settings.onRunFailed) settings.onRunFailed(campaign.id, result);
                    store.log(c).append(record);
                    ++done;
                    if (settings.onRunDone) settings.onRunDone(campaign.id, done, total);
                }
                std::lock_guard<std::mutex> lock(slots[c].mutex);
                if (--slots[c].pending == 0 && campaign.forested) slots[c].scene.reset();
            } catch (const std::exception& e) {
                std::lock_guard<std::mutex> lock(storeMutex);
                if (!failure) failure = inCampaign(campaign, e);
                stop = true;
            }
        }
    };
    int threads = settings.threads > 0 ? settings.threads : static_cast<int>(std::thread::hardware_concurrency());
    threads = std::max(1, std::min(threads, total));
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace sylva::assess
