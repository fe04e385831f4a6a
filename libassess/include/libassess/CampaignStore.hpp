#pragma once
// The output directory of an assessment as the campaign's memory: its design (design.txt), one run log
// per campaign (runs/<id>.csv, see RunLog) and the statistics of each generated forest
// (forests/<id>.csv). Opening it for a new campaign, or to resume one, is where a wrong directory or a
// mismatched design is refused.
#include <memory>
#include <string>
#include <vector>

#include "libassess/AssessmentDesign.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libassess/RunLog.hpp"

namespace sylva::assess {

class CampaignStore {
public:
    // New campaign (resume false): `dir` must be absent or empty (else InputError: "use --resume or
    // another --out"); the design is written. Resume: the design in `dir` must be `design` (InputError
    // naming the first difference); a directory without a campaign starts a new one. Then every
    // campaign's run log is opened, dropping interrupted lines (reported in notes()).
    // While the store is open, it holds an exclusive lock on the folder (flock): a second assess (or
    // a second MPI job) on the same folder is refused with InputError instead of mixing its runs in.
    CampaignStore(std::string dir, const AssessmentDesign& design, const std::vector<Campaign>& plan, bool resume);
    ~CampaignStore();
    CampaignStore(const CampaignStore&) = delete;
    CampaignStore& operator=(const CampaignStore&) = delete;

    const std::string& dir() const { return dir_; }
    bool resumed() const { return resumed_; }  // false when a new campaign was started
    RunLog& log(std::size_t campaign) { return *logs_.at(campaign); }
    const RunLog& log(std::size_t campaign) const { return *logs_.at(campaign); }
    std::string forestSummaryPath(const Campaign& campaign) const;
    const std::vector<std::string>& notes() const { return notes_; }
    void note(std::string text) { notes_.push_back(std::move(text)); }

private:
    void lockFolder();
    std::string dir_;
    int lock_ = -1;  // the folder's file descriptor, holding its lock
    bool resumed_ = false;
    std::vector<std::unique_ptr<RunLog>> logs_;  // in plan order
    std::vector<std::string> notes_;
};

}  // namespace sylva::assess
