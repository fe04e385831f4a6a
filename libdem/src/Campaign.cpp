#include "libdem/Campaign.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <fstream>
#include <mutex>
#include <string>

#include <unistd.h>

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

namespace {

// A campaign keeps every run's record until it is written: runs beyond the machine's memory would
// fail in the allocator, or in the kernel's out-of-memory killer, after the index alone had taken
// gigabytes. Half the physical memory leaves room for what the records hold besides themselves.
// In a container the cgroup's limit (cgroup v2's memory.max, "max" when there is none) is the
// machine's memory.
double availableMemory() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageBytes = sysconf(_SC_PAGE_SIZE);
    double bytes = pages > 0 && pageBytes > 0 ? static_cast<double>(pages) * static_cast<double>(pageBytes) : 0;
    double limit = 0;
    if (std::ifstream("/sys/fs/cgroup/memory.max") >> limit && limit > 0) bytes = bytes > 0 ? std::min(bytes, limit) : limit;
    return bytes;
}

void requireMemoryFor(long runs) {
    const double physical = availableMemory();
    if (!(physical > 0)) return;  // not known here: the allocator will say
    const double needed = static_cast<double>(runs) * static_cast<double>(sizeof(RunResult) + sizeof(int));
    if (needed <= 0.5 * physical) return;
    const auto gb = [](double bytes) { return readableNumber(static_cast<double>(static_cast<long>(bytes / 1e8)) / 10); };
    throw InputError(std::to_string(runs) + " runs: a campaign keeps every run's record in memory until it writes "
                     "them, at least " + gb(needed) + " GB here, more than half of this machine's " + gb(physical) +
                     " GB: split it into campaigns of fewer runs (each with its own --seed)");
}

}  // namespace

std::vector<RunResult> runCampaign(const Scene& scene, const CampaignOptions& options) {
    requireMemoryFor(options.only.empty() ? options.runs : static_cast<long>(options.only.size()));
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
