#pragma once
// The output directory of an assessment as the campaign's memory: one SQLite database,
// OUT/campaign.sqlite, holding the design, the campaigns of the plan, every finished run and the
// statistics of each generated forest (docs/assessment.md gives the schema and queries from R and
// Python). A run is stored in one transaction with its forest's statistics, so a kill at any moment
// leaves either the run or nothing; rows carry checksums, so an edited run or forest is run again
// rather than believed. Opening it for a new campaign, or to resume one, is where a wrong directory
// or a mismatched design is refused.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "libassess/AssessmentDesign.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libassess/ForestSummary.hpp"
#include "libassess/RunRecord.hpp"

namespace sylva::assess {

class SqliteDatabase;
class SqliteStatement;

class FolderLock;

class CampaignStore {
public:
    static constexpr int kSchemaVersion = 2;  // PRAGMA user_version of campaign.sqlite (2: campaigns.model)
    static const char* const kFileName;       // "campaign.sqlite"

    // New campaign (resume false): `dir` must be absent or empty (else InputError: "use --resume or
    // another --out"); the design and plan are written in one transaction. Resume: the design stored
    // there must be `design` (InputError naming the first difference); a folder whose campaign was
    // killed before its design was committed starts a new one. Rows whose checksum fails are dropped
    // (their runs are run again, reported in notes()); a run of another seed or outside the plan, or a
    // store of another schema version, is refused naming the file.
    // While the store is open, it holds an exclusive lock on the folder (flock): a second assess (or
    // a second MPI job) on the same folder is refused with InputError instead of mixing its runs in.
    CampaignStore(std::string dir, const AssessmentDesign& design, const std::vector<Campaign>& plan, bool resume);
    ~CampaignStore();
    CampaignStore(const CampaignStore&) = delete;
    CampaignStore& operator=(const CampaignStore&) = delete;

    const std::string& dir() const { return dir_; }
    std::string path() const;  // of the database
    bool resumed() const { return resumed_; }  // false when a new campaign was started

    const std::map<int, RunRecord>& runs(std::size_t campaign) const { return runs_.at(campaign); }  // by run index
    std::vector<int> missingRuns(std::size_t campaign) const;
    const std::optional<ForestSummary>& forest(std::size_t campaign) const { return forests_.at(campaign); }

    // One transaction: the run and, with it, its forest's statistics when given. Not thread-safe:
    // callers serialise.
    void save(std::size_t campaign, const RunRecord& run, const ForestSummary* forest = nullptr);
    void saveForest(std::size_t campaign, const ForestSummary& forest);

    const std::vector<std::string>& notes() const { return notes_; }
    void note(std::string text) { notes_.push_back(std::move(text)); }

private:
    void create(const AssessmentDesign& design);
    void checkStored(const AssessmentDesign& design);
    void loadRuns();
    void loadForests();
    SqliteStatement& statement(std::unique_ptr<SqliteStatement>& slot, const char* sql);
    void insertForest(const std::string& campaign, const ForestSummary& summary);
    std::string dir_;
    std::unique_ptr<FolderLock> lock_;
    bool resumed_ = false;
    std::vector<Campaign> plan_;
    std::unique_ptr<SqliteDatabase> db_;
    std::unique_ptr<SqliteStatement> insertRun_, insertForest_;  // after db_: destroyed before it
    std::vector<std::map<int, RunRecord>> runs_;           // in plan order
    std::vector<std::optional<ForestSummary>> forests_;  // in plan order
    std::vector<std::string> notes_;
};

}  // namespace sylva::assess
