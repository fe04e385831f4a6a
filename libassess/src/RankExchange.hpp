#pragma once
// How the ranks of a campaign spread by mpirun talk while it runs: every thread of every rank asks rank
// 0 for a job, handing in the bytes of the one it finished (nothing on its first request); rank 0
// answers each request at once with the next job's bytes, or with a stop. A rank whose threads have
// all stopped says it is done. Rank 0's own threads do not send messages: they ask the same `answer`
// directly.
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "libassess/MpiWorld.hpp"
#include "libcommon/ThreadTeam.hpp"

namespace sylva::assess {

// Records what `rank` finished and returns its next job, or nothing to stop it. Called from one
// thread at a time only if the caller serialises it: rank 0's threads call it too.
using AnswerRank = std::function<std::optional<std::string>(int rank, std::optional<std::string> finished)>;

// Rank 0: runs `ownWork` (its threads' share) while answering the other ranks until each said it is
// done. If MPI fails, `stop` is told (so that ownWork ends soon), ownWork is waited for and the
// failure rethrown. With one rank, only runs ownWork.
void coordinateRanks(const MpiWorld& world, const std::function<void()>& ownWork, const AnswerRank& answer,
                     const std::function<void(std::exception_ptr)>& stop);

// Another rank: what its threads call to hand in a job and get the next; they take turns.
class CoordinatorLink {
public:
    explicit CoordinatorLink(const MpiWorld& world) : world_(world) {}
    std::optional<std::string> exchange(const std::optional<std::string>& finished);
    void done();  // after this rank's threads have all stopped

private:
    const MpiWorld& world_;
    std::mutex turn_;  // MPI_THREAD_SERIALIZED
};

// `threads` threads of this rank, each asking `exchange` for a job, doing it with `work` and handing in
// the outcome with its next request, until `exchange` has no job left.
template <class Job, class Outcome>
void workOnThreads(int threads, const std::function<std::optional<Job>(std::optional<Outcome> finished)>& exchange,
                   const std::function<Outcome(const Job&)>& work) {
    runOnThreads(threads, [&] {
        std::optional<Outcome> finished;
        while (const std::optional<Job> job = exchange(std::move(finished))) finished = work(*job);
    });
}

}  // namespace sylva::assess
