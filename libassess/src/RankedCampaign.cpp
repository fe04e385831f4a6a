#include "libassess/RankedCampaign.hpp"

#include <algorithm>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>

#include "Bytes.hpp"
#include "RankExchange.hpp"
#include "RunResultMessage.hpp"
#include "libassess/MpiWorld.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

namespace {

// A batch of runs: slots [first, first + size) of the campaign's run list.
struct Batch {
    int first = 0;
};

struct BatchOutcome {
    Batch batch;
    std::vector<dem::RunResult> results;
    std::string error;  // the batch could not run (runCampaign threw)
    bool inputError = false;
};

std::string encode(const BatchOutcome& o) {
    ByteWriter w;
    w.put(o.batch.first).put(static_cast<std::uint64_t>(o.results.size()));
    for (const auto& r : o.results) put(w, r);
    w.put(o.error).put(o.inputError);
    return w.take();
}

BatchOutcome decodeBatchOutcome(const std::string& bytes) {
    ByteReader r(bytes);
    BatchOutcome o;
    o.batch.first = r.get<int>();
    o.results.resize(r.count(1));
    for (auto& result : o.results) result = getRunResult(r);
    o.error = r.getString();
    o.inputError = r.get<bool>();
    r.end();
    return o;
}

}  // namespace

std::vector<dem::RunResult> runCampaignOnRanks(const dem::Scene& scene, const dem::CampaignOptions& options) {
    const MpiWorld& world = MpiWorld::current();
    if (world.size() == 1) return dem::runCampaign(scene, options);

    std::vector<int> indices = options.only;
    if (indices.empty())
        for (int i = 0; i < options.runs; ++i) indices.push_back(i);
    const int total = static_cast<int>(indices.size());
    // Some 64 batches per rank: small enough to even out runs of very different cost, large enough
    // that thousands of millisecond runs (the lumped model) do not each cost a message.
    const int batchSize = std::max(1, total / (64 * world.size()));

    const std::function<BatchOutcome(const Batch&)> runBatch = [&](const Batch& b) {
        BatchOutcome o;
        o.batch = b;
        dem::CampaignOptions one = options;
        one.only.assign(indices.begin() + b.first, indices.begin() + std::min(total, b.first + batchSize));
        one.threads = 1;
        one.onRunDone = nullptr;
        try {
            o.results = dem::runCampaign(scene, one);
        } catch (const std::exception& e) {
            o.error = e.what();
            o.inputError = dynamic_cast<const InputError*>(&e) != nullptr;
        }
        return o;
    };
    const int threads = threadsFor(options.threads, (total + batchSize - 1) / batchSize);

    if (!world.coordinator()) {
        CoordinatorLink link(world);
        const std::function<std::optional<Batch>(std::optional<BatchOutcome>)> remote = [&](std::optional<BatchOutcome> finished) {
            const auto job = link.exchange(finished ? std::optional<std::string>(encode(*finished)) : std::nullopt);
            return job ? std::optional<Batch>(Batch{std::stoi(*job)}) : std::nullopt;
        };
        workOnThreads(threads, remote, runBatch);
        link.done();
        return {};
    }

    std::vector<dem::RunResult> results(static_cast<std::size_t>(total));
    std::mutex mutex;
    int next = 0, done = 0;
    std::exception_ptr failure;
    const std::function<std::optional<Batch>(std::optional<BatchOutcome>)> own = [&](std::optional<BatchOutcome> finished) {
        std::lock_guard<std::mutex> lock(mutex);
        if (finished && !finished->error.empty() && !failure)
            failure = finished->inputError ? std::make_exception_ptr(InputError(finished->error))
                                           : std::make_exception_ptr(std::runtime_error(finished->error));
        if (finished)
            for (std::size_t k = 0; k < finished->results.size(); ++k) {
                auto& slot = results[static_cast<std::size_t>(finished->batch.first) + k];
                slot = std::move(finished->results[k]);
                if (options.onRunDone) options.onRunDone(slot, ++done, total);
            }
        if (failure || next >= total) return std::optional<Batch>();
        const Batch b{next};
        next += batchSize;
        return std::optional<Batch>(b);
    };
    const AnswerRank answer = [&](int, std::optional<std::string> finished) -> std::optional<std::string> {
        const std::optional<Batch> b = own(finished ? std::optional<BatchOutcome>(decodeBatchOutcome(*finished)) : std::nullopt);
        return b ? std::optional<std::string>(std::to_string(b->first)) : std::nullopt;
    };
    coordinateRanks(world, [&] { workOnThreads(threads, own, runBatch); }, answer, [&](std::exception_ptr e) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = e;
    });
    if (failure) std::rethrow_exception(failure);
    return results;
}

}  // namespace sylva::assess
