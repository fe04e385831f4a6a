#pragma once
// One run of one campaign as the runner hands it out, and what running it gave back; both travel as
// bytes between MPI ranks (all ranks run the same executable, so the layout is the sender's).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "libassess/ForestSummary.hpp"

namespace sylva::assess {

struct CampaignJob {
    std::size_t campaign = 0;  // index in the plan
    int run = 0;
    bool summarise = false;    // also bring back the statistics of the campaign's forest
};

struct JobOutcome {
    CampaignJob job;
    std::string record;   // formatRunLine of the run (17 digits: the coordinator stores the very doubles)
    std::string failure;  // the run stopped on a numerical error (stored as failed): why
    std::optional<ForestSummary> forest;  // when job.summarise
    std::string error;    // the job could not be run at all (empty: it ran)
    bool inputError = false;  // error came from the user's input (exit status 2), not from the code
};

std::string encode(const CampaignJob& job);
CampaignJob decodeJob(const std::string& bytes);
std::string encode(const JobOutcome& outcome);
JobOutcome decodeOutcome(const std::string& bytes);

}  // namespace sylva::assess
