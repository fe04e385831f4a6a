#include "RankExchange.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

namespace sylva::assess {

namespace {
// A request carries a finished job (or nothing); the answer is a job or a stop; kDone ends a rank.
enum Tag : int { kRequest = 1, kJob = 2, kStop = 3, kDone = 4 };
}  // namespace

void coordinateRanks(const MpiWorld& world, const std::function<void()>& ownWork, const AnswerRank& answer,
                     const std::function<void(std::exception_ptr)>& stop) {
    if (world.size() == 1) return ownWork();
    std::thread own(ownWork);
    std::exception_ptr failure;
    try {
        for (int done = 0; done < world.size() - 1;) {
            std::optional<MpiWorld::Message> m = world.poll();
            if (!m) {
                // Polling rather than a blocking receive: Open MPI's blocking calls spin, and this rank's
                // own threads need the core.
                std::this_thread::sleep_for(std::chrono::microseconds(200));
            } else if (m->tag == kDone) {
                ++done;
            } else {
                std::optional<std::string> finished;
                if (!m->bytes.empty()) finished = std::move(m->bytes);
                const std::optional<std::string> job = answer(m->source, std::move(finished));
                world.send(m->source, job ? kJob : kStop, job ? *job : std::string());
            }
        }
    } catch (const std::exception&) {
        // MPI itself failed: this rank's threads stop after their runs, and its exit makes mpirun end
        // the others.
        failure = std::current_exception();
        stop(failure);
    }
    own.join();
    if (failure) std::rethrow_exception(failure);
}

std::optional<std::string> CoordinatorLink::exchange(const std::optional<std::string>& finished) {
    std::lock_guard<std::mutex> lock(turn_);
    world_.send(0, kRequest, finished ? *finished : std::string());
    MpiWorld::Message reply = world_.receive(0);
    if (reply.tag != kJob) return std::nullopt;
    return std::move(reply.bytes);
}

void CoordinatorLink::done() { world_.send(0, kDone, {}); }

}  // namespace sylva::assess
