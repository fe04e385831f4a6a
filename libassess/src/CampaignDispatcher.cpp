#include "CampaignDispatcher.hpp"

#include <algorithm>
#include <stdexcept>

#include "libassess/ForestSummary.hpp"
#include "libassess/RunRecord.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

CampaignDispatcher::CampaignDispatcher(const std::vector<Campaign>& plan, CampaignStore& store, const RunnerSettings& settings)
    : plan_(plan), store_(store), settings_(settings), left_(plan.size()), teamsOn_(plan.size(), 0),
      summaryAsked_(plan.size(), false) {
    for (std::size_t c = 0; c < plan.size(); ++c) {
        left_[c] = store.missingRuns(c);
        std::reverse(left_[c].begin(), left_[c].end());
        total_ += static_cast<int>(left_[c].size());
    }
}

std::optional<CampaignJob> CampaignDispatcher::exchange(int team, std::optional<JobOutcome> finished) {
    std::lock_guard<std::mutex> lock(mutex_);
    try {
        if (finished) store(std::move(*finished));
    } catch (const std::exception&) {  // the store could not be written: no use running more
        if (!failure_) failure_ = std::current_exception();
    }
    return next(team);
}

void CampaignDispatcher::fail(std::exception_ptr error) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!failure_) failure_ = std::move(error);
}

void CampaignDispatcher::store(JobOutcome&& o) {
    const Campaign& campaign = plan_.at(o.job.campaign);
    const auto failed = [&](const std::string& what, bool input) {
        if (failure_) return;
        const std::string text = "campaign " + campaign.id + ": " + what;
        failure_ = input ? std::make_exception_ptr(InputError(text)) : std::make_exception_ptr(std::runtime_error(text));
    };
    if (!o.error.empty()) return failed(o.error, o.inputError);
    const std::optional<RunRecord> record = parseRunLine(o.record);
    if (!record || record->run != o.job.run) return failed("run " + std::to_string(o.job.run) + " came back garbled", false);
    if (!o.failure.empty() && settings_.onRunFailed) settings_.onRunFailed(campaign.id, *record, o.failure);
    store_.save(o.job.campaign, *record, o.forest ? &*o.forest : nullptr);
    ++done_;
    if (settings_.onRunDone) settings_.onRunDone(campaign.id, done_, total_);
}

std::optional<CampaignJob> CampaignDispatcher::next(int team) {
    if (failure_) return std::nullopt;
    auto on = teamCampaign_.find(team);
    if (on == teamCampaign_.end() || left_[on->second].empty()) {
        if (on != teamCampaign_.end()) --teamsOn_[on->second];
        std::optional<std::size_t> best;
        const auto better = [&](std::size_t c, std::size_t than) {
            if ((teamsOn_[c] == 0) != (teamsOn_[than] == 0)) return teamsOn_[c] == 0;
            return left_[c].size() > left_[than].size();
        };
        for (std::size_t c = 0; c < left_.size(); ++c)
            if (!left_[c].empty() && (!best || better(c, *best))) best = c;
        if (!best) {
            if (on != teamCampaign_.end()) teamCampaign_.erase(on);
            return std::nullopt;
        }
        ++teamsOn_[*best];
        on = teamCampaign_.insert_or_assign(team, *best).first;
    }
    CampaignJob job;
    job.campaign = on->second;
    job.run = left_[job.campaign].back();
    left_[job.campaign].pop_back();
    job.summarise = plan_[job.campaign].forested && !summaryAsked_[job.campaign];
    summaryAsked_[job.campaign] = true;
    return job;
}

void CampaignDispatcher::rethrowFailure() const {
    if (failure_) std::rethrow_exception(failure_);
}

}  // namespace sylva::assess
