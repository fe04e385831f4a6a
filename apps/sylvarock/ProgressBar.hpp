#pragma once
// Progress of long campaigns on standard error: a bar redrawn in place on a terminal; elsewhere (a log
// file, a batch job's output) a line at each tenth of the runs once 5 s have passed, which the log keeps
// and a killed run leaves behind.
#include <chrono>
#include <string>

namespace sylva::cli {

class ProgressBar {
public:
    explicit ProgressBar(bool terminal);
    // `label` names what is running (e.g. a campaign); the time left is extrapolated from the rate so far.
    void update(int done, int total, const std::string& label = {});

private:
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
    int lastTenth_ = 0, lastDone_ = 0;
};

}  // namespace sylva::cli
