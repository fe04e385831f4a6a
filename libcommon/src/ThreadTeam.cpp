#include "libcommon/ThreadTeam.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace sylva {

int threadsFor(int requested, long jobs) {
    const long threads = requested > 0 ? requested : static_cast<long>(std::thread::hardware_concurrency());
    return static_cast<int>(std::max(1L, std::min(threads, jobs)));
}

void runOnThreads(int threads, const std::function<void()>& loop) {
    std::mutex mutex;
    std::exception_ptr failure;
    const auto guarded = [&] {
        try {
            loop();
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex);
            if (!failure) failure = std::current_exception();
        }
    };
    std::vector<std::thread> team;
    for (int t = 0; t < threads; ++t) team.emplace_back(guarded);
    for (auto& t : team) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace sylva
