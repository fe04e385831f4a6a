#pragma once
// The file of one campaign's finished runs (a forest realisation's, or the baseline's), written run by
// run so that a campaign killed at any moment resumes where it stopped.
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "libassess/RunRecord.hpp"

namespace sylva::assess {

class RunLog {
public:
    // Opens the log of a campaign of `runs` runs seeded with `campaignSeed`, creating it (header only)
    // if absent. Valid lines of an existing log are kept. A line cut short by a kill (no newline at the
    // end of the file) or failing its checksum is dropped with a note in `notes` (its run will be
    // redone), and the file is rewritten without it before anything is appended. InputError (file and
    // line) for a wrong header, a run index outside [0, runs), a seed that is not this campaign's, or
    // two different results for one run.
    RunLog(std::string path, int runs, std::uint64_t campaignSeed, std::vector<std::string>& notes);
    ~RunLog();
    RunLog(const RunLog&) = delete;
    RunLog& operator=(const RunLog&) = delete;

    const std::map<int, RunRecord>& records() const { return records_; }  // by run index
    std::vector<int> missingRuns() const;
    // Appends one line and flushes it to the operating system, so a kill loses only the runs still in
    // progress. Not thread-safe: callers serialise.
    void append(const RunRecord& record);

private:
    void rewrite() const;
    std::string path_;
    int runs_;
    std::map<int, RunRecord> records_;
    std::FILE* file_ = nullptr;
};

}  // namespace sylva::assess
