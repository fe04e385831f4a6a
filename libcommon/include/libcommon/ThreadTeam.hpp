#pragma once
// The one way sylvarock uses a machine's cores: a team of threads that each run the same loop (taking
// work from a shared source until it runs dry), all joined before the call returns. Which work a
// thread takes never changes a result: every run is seeded by its own index.
#include <functional>

namespace sylva {

// `requested` threads (0: one per core), at least 1 and at most `jobs`.
int threadsFor(int requested, long jobs);

// Runs `loop` on `threads` threads and joins them; an exception that escapes a thread's loop is
// rethrown here (the first one), after every thread has ended.
void runOnThreads(int threads, const std::function<void()>& loop);

}  // namespace sylva
