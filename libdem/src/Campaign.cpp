#include "libdem/Campaign.hpp"

#include <atomic>
#include <exception>
#include <mutex>

#include "libdem/LumpedRun.hpp"
#include "libdem/SimulationError.hpp"
#include "libcommon/InputError.hpp"
#include "libcommon/ThreadTeam.hpp"

namespace sylva::dem {

std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}

std::uint64_t runSeed(std::uint64_t campaignSeed, int run) {
    // gsl's mt19937 takes an unsigned long seed; keep it in 32 bits so it means the same everywhere.
    return splitmix64(splitmix64(campaignSeed) ^ static_cast<std::uint64_t>(run)) & 0xFFFFFFFFULL;
}

Model parseModel(const std::string& name) {
    if (name == "dem") return Model::Dem;
    if (name == "lumped") return Model::Lumped;
    throw InputError("model '" + name + "': expected dem (the discrete element model) or lumped (the lumped-mass model, docs/lumped.md)");
}

std::string toString(Model m) { return m == Model::Dem ? "dem" : "lumped"; }

std::vector<RunResult> runCampaign(const Scene& scene, const CampaignOptions& options) {
    std::vector<int> indices = options.only;
    if (indices.empty())
        for (int i = 0; i < options.runs; ++i) indices.push_back(i);
    const int total = static_cast<int>(indices.size());
    std::vector<RunResult> results(total);
    std::atomic<int> next{0};
    std::mutex mutex;
    int done = 0;
    std::exception_ptr failure;
    auto worker = [&] {
        for (;;) {
            const int slot = next.fetch_add(1);
            if (slot >= total) return;
            const int i = indices[slot];
            {
                std::lock_guard<std::mutex> lock(mutex);
                if (failure) return;
            }
            try {
                const std::uint64_t seed = runSeed(options.seed, i);
                RunResult r = options.model == Model::Dem ? simulateBlock(scene, i, seed, options.run)
                                                          : simulateLumped(scene, i, seed, options.run);
                std::lock_guard<std::mutex> lock(mutex);
                results[slot] = std::move(r);
                ++done;
                if (options.onRunDone) options.onRunDone(results[slot], done, total);
            } catch (const SimulationError& e) {
                RunResult r = failedRun(scene, i, runSeed(options.seed, i), e.what());
                std::lock_guard<std::mutex> lock(mutex);
                results[slot] = std::move(r);
                ++done;
                if (options.onRunDone) options.onRunDone(results[slot], done, total);
            } catch (...) {
                std::lock_guard<std::mutex> lock(mutex);
                if (!failure) failure = std::current_exception();
            }
        }
    };
    runOnThreads(threadsFor(options.threads, total), worker);
    if (failure) std::rethrow_exception(failure);
    return results;
}

}  // namespace sylva::dem
