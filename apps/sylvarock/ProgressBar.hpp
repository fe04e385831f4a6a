#pragma once
// A one-line progress bar on standard error for long campaigns, drawn only on a terminal.
#include <chrono>
#include <string>

namespace sylva::cli {

class ProgressBar {
public:
    explicit ProgressBar(bool enabled);
    // `label` names what is running (e.g. a campaign); the time left is extrapolated from the rate so far.
    void update(int done, int total, const std::string& label = {});

private:
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace sylva::cli
