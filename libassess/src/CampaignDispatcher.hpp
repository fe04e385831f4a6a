#pragma once
// The coordinator of an assessment's missing runs (the only process that writes the store): it hands
// each team (the threads of one MPI rank, or of the one process) its next run and stores what the
// team finished. Teams take work as they free up, so a rank that drew a long run does not hold the
// others back. A team stays on its campaign while runs are left there and otherwise moves to the
// campaign with the most runs left that no team works on: each rank then builds few forest scenes.
// Which team ran a run never shows in the results: a run depends on its seed alone.
#include <cstddef>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

#include "CampaignJob.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libassess/CampaignRunner.hpp"
#include "libassess/CampaignStore.hpp"

namespace sylva::assess {

class CampaignDispatcher {
public:
    CampaignDispatcher(const std::vector<Campaign>& plan, CampaignStore& store, const RunnerSettings& settings);

    int runsToDo() const { return total_; }
    // Stores what `team` finished (if anything) and gives it its next job; nothing once every run is
    // handed out or a job failed. Thread-safe.
    std::optional<CampaignJob> exchange(int team, std::optional<JobOutcome> finished);
    // Stops handing out jobs because of `error` (unless a job failed before).
    void fail(std::exception_ptr error);
    // Once every team has stopped: rethrows the first failure (a job that could not run, named with
    // its campaign, or a run that could not be stored).
    void rethrowFailure() const;

private:
    void store(JobOutcome&& outcome);
    std::optional<CampaignJob> next(int team);

    const std::vector<Campaign>& plan_;
    CampaignStore& store_;
    const RunnerSettings& settings_;
    std::mutex mutex_;
    std::vector<std::vector<int>> left_;  // per campaign: runs not handed out, last one next
    std::vector<int> teamsOn_;            // per campaign: teams whose last job came from it
    std::vector<bool> summaryAsked_;
    std::map<int, std::size_t> teamCampaign_;
    int total_ = 0, done_ = 0;
    std::exception_ptr failure_;
};

}  // namespace sylva::assess
