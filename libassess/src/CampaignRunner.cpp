#include "libassess/CampaignRunner.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>

#include "CampaignDispatcher.hpp"
#include "CampaignJob.hpp"
#include "JobRunner.hpp"
#include "libassess/ForestSummary.hpp"
#include "libassess/MpiWorld.hpp"
#include "libstand/ForestGenerator.hpp"
#include "libstand/InputError.hpp"

namespace sylva::assess {

namespace {

constexpr double kUnforestedRunM = 30;  // Sect. 2.3.2: the blocks reach ~15 m/s before the forest

// Tags of the runners' messages. A worker's request carries the outcome of its last job (empty on its
// first request); the coordinator answers each with a job or with kStop; a worker whose threads have
// all stopped says kDone.
enum Tag : int { kRequest = 1, kJob = 2, kStop = 3, kDone = 4 };

using Exchange = std::function<std::optional<CampaignJob>(std::optional<JobOutcome> finished)>;

// `threads` threads, each running jobs until `exchange` has none left, handing in each outcome as it
// asks for the next job.
void runThreads(int threads, JobRunner& runner, const Exchange& exchange) {
    auto work = [&] {
        std::optional<JobOutcome> finished;
        while (const std::optional<CampaignJob> job = exchange(std::move(finished))) finished = runner.run(*job);
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(work);
    for (auto& t : pool) t.join();
}

int threadCount(int requested, int jobs) {
    const int threads = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
    return std::max(1, std::min(threads, jobs));
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
    for (std::size_t c = 0; c < plan.size(); ++c) {
        if (!plan[c].forested || !store.log(c).missingRuns().empty() || forestSummaryIntact(store.forestSummaryPath(plan[c])))
            continue;
        // All runs are stored but the forest's statistics were lost, damaged or edited: only they are
        // computed again (the forest is its seed's).
        if (std::filesystem::exists(store.forestSummaryPath(plan[c])))
            store.note(store.forestSummaryPath(plan[c]) + ": checksum mismatch (edited or damaged): computed again");
        const stand::Window extent = forestExtent(*bareScene);
        writeForestSummary(store.forestSummaryPath(plan[c]),
                           summariseForest(campaignForest(plan[c], catalogues.at(plan[c].stand), extent), extent));
    }
    CampaignDispatcher dispatcher(plan, store, settings);
    JobRunner runner(plan, bareScene, catalogues);
    const MpiWorld& world = MpiWorld::current();
    const int localThreads = threadCount(settings.threads, dispatcher.runsToDo());
    const Exchange local = [&](std::optional<JobOutcome> finished) { return dispatcher.exchange(0, std::move(finished)); };
    if (world.size() == 1) {
        if (dispatcher.runsToDo() > 0) runThreads(localThreads, runner, local);
    } else {
        // This rank's threads run jobs too; the main thread answers the other ranks.
        std::thread own([&] { runThreads(localThreads, runner, local); });
        try {
            for (int done = 0; done < world.size() - 1;) {
                std::optional<MpiWorld::Message> m = world.poll();
                if (!m) {
                    std::this_thread::sleep_for(std::chrono::microseconds(200));
                } else if (m->tag == kDone) {
                    ++done;
                } else {
                    std::optional<JobOutcome> finished;
                    if (!m->bytes.empty()) finished = decodeOutcome(m->bytes);
                    const std::optional<CampaignJob> job = dispatcher.exchange(m->source, std::move(finished));
                    world.send(m->source, job ? kJob : kStop, job ? encode(*job) : std::string());
                }
            }
        } catch (const std::exception&) {
            // MPI itself failed: this rank's threads stop after their runs, and its exit makes mpirun
            // end the others.
            dispatcher.fail(std::current_exception());
        }
        own.join();
    }
    dispatcher.rethrowFailure();
}

void serveCampaigns(const std::vector<Campaign>& plan, std::shared_ptr<const dem::Scene> bareScene,
                    const std::vector<stand::StandCatalogue>& catalogues, const RunnerSettings& settings) {
    const MpiWorld& world = MpiWorld::current();
    JobRunner runner(plan, bareScene, catalogues);
    std::mutex turn;  // one thread at a time talks to the coordinator (MPI_THREAD_SERIALIZED)
    const Exchange remote = [&](std::optional<JobOutcome> finished) -> std::optional<CampaignJob> {
        std::lock_guard<std::mutex> lock(turn);
        world.send(0, kRequest, finished ? encode(*finished) : std::string());
        const MpiWorld::Message reply = world.receive(0);
        if (reply.tag != kJob) return std::nullopt;
        return decodeJob(reply.bytes);
    };
    runThreads(threadCount(settings.threads, std::numeric_limits<int>::max()), runner, remote);
    world.send(0, kDone, {});
}

}  // namespace sylva::assess
