#include "libassess/CampaignStore.hpp"

#include <filesystem>
#include <sstream>

#include "FolderLock.hpp"
#include "SqliteDatabase.hpp"
#include "libdem/Campaign.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

const char* const CampaignStore::kFileName = "campaign.sqlite";

namespace {

// Tidy tables: one row per observation, one column per variable, units in the names, so that R and
// Python read them as they are (docs/assessment.md). Seeds are below 2^32, exact in R's doubles too.
const char* const kSchema = R"(
CREATE TABLE design (line INTEGER PRIMARY KEY, text TEXT NOT NULL);
CREATE TABLE campaigns (
  id TEXT PRIMARY KEY, position INTEGER NOT NULL UNIQUE, model TEXT NOT NULL, stand TEXT, structure TEXT, realisation INTEGER,
  runs INTEGER NOT NULL, run_seed INTEGER NOT NULL, forest_seed INTEGER);
CREATE TABLE runs (
  campaign TEXT NOT NULL REFERENCES campaigns(id), run INTEGER NOT NULL, seed INTEGER NOT NULL,
  runout_m REAL, runout_horizontal_m REAL, stop_x_m REAL, stop_y_m REAL, stop_z_m REAL,
  energy_line_deg REAL, max_speed_m_s REAL, tree_impacts INTEGER, reason TEXT NOT NULL, checksum TEXT NOT NULL,
  PRIMARY KEY (campaign, run)) WITHOUT ROWID;
CREATE TABLE forests (
  campaign TEXT PRIMARY KEY REFERENCES campaigns(id), stems INTEGER, stems_per_ha REAL, basal_area_m2_ha REAL,
  mean_dbh_cm REAL, sd_dbh_cm REAL, clark_evans REAL, checksum TEXT NOT NULL);
)";

bool isStoreFile(const fs::path& p) {
    const std::string name = p.filename().string(), base = CampaignStore::kFileName;
    return name == base || name == base + "-wal" || name == base + "-shm" || name == base + "-journal";
}

// Whether the folder holds anything but a campaign store's files.
bool holdsOtherFiles(const std::string& dir) {
    for (const auto& entry : fs::directory_iterator(dir))
        if (!isStoreFile(entry.path())) return true;
    return false;
}

// A store whose design was committed holds a campaign; one killed before that commit (the schema,
// design and plan are one transaction) holds nothing and is started afresh.
bool holdsCampaign(SqliteDatabase& db) {
    auto tables = db.prepare("SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = 'design'");
    if (!tables.step() || tables.integer(0) == 0) return false;
    auto lines = db.prepare("SELECT count(*) FROM design");
    return lines.step() && lines.integer(0) > 0;
}

std::string structureOf(const Campaign& c) { return c.forested ? structureCode(c.structure) : std::string(); }

}  // namespace

CampaignStore::CampaignStore(std::string dir, const AssessmentDesign& design, const std::vector<Campaign>& plan, bool resume)
    : dir_(std::move(dir)), plan_(plan), runs_(plan.size()), forests_(plan.size()) {
    if (fs::exists(dir_) && !fs::is_directory(dir_)) throw InputError("--out " + dir_ + ": exists and is not a directory");
    fs::create_directories(dir_);
    lock_ = std::make_unique<FolderLock>(dir_, "assess");
    const bool otherFiles = holdsOtherFiles(dir_);
    const bool hasStore = fs::exists(path());
    if (!hasStore && otherFiles) {
        if (!resume) throw InputError("--out " + dir_ + " is not empty: use another --out (or --resume to continue a campaign in it)");
        if (fs::exists(fs::path(dir_) / "design.txt"))
            throw InputError("--out " + dir_ + " holds a campaign written by an earlier sylvarock (text run logs, design.txt), "
                             "which this version does not resume: run it again in another --out");
        throw InputError(path(), 0, "missing: " + dir_ + " is not the output of sylvarock assess, nothing to resume");
    }
    db_ = std::make_unique<SqliteDatabase>(path(), true);
    // A kill at any moment leaves the last committed run: WAL with synchronous NORMAL is atomic and
    // consistent after a process crash (a power cut may lose the last few runs, never corrupt).
    db_->execute("PRAGMA journal_mode = WAL; PRAGMA synchronous = NORMAL; PRAGMA foreign_keys = ON");
    if (!holdsCampaign(*db_)) {
        if (otherFiles) throw InputError("--out " + dir_ + " is not empty and holds no campaign: use another --out");
        if (resume) notes_.push_back(dir_ + " holds no campaign yet: starting a new one");
        create(design);
        return;
    }
    if (!resume) throw InputError("--out " + dir_ + " is not empty: use --resume to continue the campaign in it, or another --out");
    checkStored(design);
    resumed_ = true;
    loadRuns();
    loadForests();
}

CampaignStore::~CampaignStore() {
    insertRun_.reset();  // statements are finalised before their database closes
    insertForest_.reset();
    db_.reset();  // closes the database (checkpointing its log) before the lock goes
    lock_.reset();
}

std::string CampaignStore::path() const { return (fs::path(dir_) / kFileName).string(); }

// Schema, design and plan in one transaction: a kill before its commit leaves a store without a
// campaign, which the next assess starts afresh.
void CampaignStore::create(const AssessmentDesign& design) {
    SqliteTransaction transaction(*db_);
    db_->execute(kSchema);
    db_->execute("PRAGMA user_version = " + std::to_string(kSchemaVersion));
    auto line = db_->prepare("INSERT INTO design (line, text) VALUES (?, ?)");
    std::istringstream text(designText(design));
    std::string row;
    for (std::int64_t n = 1; std::getline(text, row); ++n) line.bind(1, n).bind(2, row).run();
    auto campaign = db_->prepare(
        "INSERT INTO campaigns (id, position, model, stand, structure, realisation, runs, run_seed, forest_seed) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
    for (std::size_t c = 0; c < plan_.size(); ++c) {
        const Campaign& p = plan_[c];
        campaign.bind(1, p.id).bind(2, static_cast<std::int64_t>(c)).bind(3, dem::toString(p.model));
        campaign.bind(4, p.forested ? design.stands.at(p.stand).name : std::string()).bind(5, structureOf(p));
        campaign.bind(6, static_cast<std::int64_t>(p.realisation)).bind(7, static_cast<std::int64_t>(p.runs));
        campaign.bind(8, static_cast<std::int64_t>(p.runSeed));
        if (p.forested)
            campaign.bind(9, static_cast<std::int64_t>(p.forestSeed));
        else
            campaign.bindNull(9);
        campaign.run();
    }
    transaction.commit();
}

void CampaignStore::checkStored(const AssessmentDesign& design) {
    auto version = db_->prepare("PRAGMA user_version");
    const std::int64_t stored = version.step() ? version.integer(0) : 0;
    if (stored != kSchemaVersion)
        throw InputError(path(), 0, "a campaign store of schema version " + std::to_string(stored) + ", this sylvarock reads version " +
                                        std::to_string(kSchemaVersion) + ": resume it with the sylvarock that started it");
    auto check = db_->prepare("PRAGMA quick_check");
    if (check.step() && check.text(0) != "ok")
        throw InputError(path(), 0, "the campaign store is damaged (" + check.text(0) + "): start the campaign again in another --out");
    std::string text;
    for (auto lines = db_->prepare("SELECT text FROM design ORDER BY line"); lines.step();) text += lines.text(0) + "\n";
    if (std::string other = requireSameDesign(text, path(), design); !other.empty()) note(std::move(other));
    // The design fixes the plan; a plan that differs is a store written by hand or by another version.
    std::size_t n = 0;
    for (auto campaigns = db_->prepare("SELECT id, runs, run_seed FROM campaigns ORDER BY position"); campaigns.step(); ++n) {
        if (n >= plan_.size() || campaigns.text(0) != plan_[n].id || campaigns.integer(1) != plan_[n].runs ||
            campaigns.integer(2) != static_cast<std::int64_t>(plan_[n].runSeed))
            throw InputError(path(), 0, "its campaigns table does not match the design (campaign " + campaigns.text(0) +
                                            "): start the campaign again in another --out");
    }
    if (n != plan_.size()) throw InputError(path(), 0, "its campaigns table lists " + std::to_string(n) + " campaigns, the design " +
                                                          std::to_string(plan_.size()) + ": start the campaign again in another --out");
}

void CampaignStore::loadRuns() {
    std::map<std::string, std::size_t> index;
    for (std::size_t c = 0; c < plan_.size(); ++c) index[plan_[c].id] = c;
    std::vector<std::pair<std::string, std::int64_t>> damaged;
    auto rows = db_->prepare(
        "SELECT campaign, run, seed, runout_m, runout_horizontal_m, stop_x_m, stop_y_m, stop_z_m, energy_line_deg, max_speed_m_s, "
        "tree_impacts, reason, checksum FROM runs ORDER BY campaign, run");
    while (rows.step()) {
        const std::string id = rows.text(0);
        const auto c = index.find(id);
        if (c == index.end()) throw InputError(path(), 0, "a run of campaign " + id + ", which is not in the design");
        const Campaign& campaign = plan_[c->second];
        RunRecord r;
        r.run = static_cast<int>(rows.integer(1));
        const std::string where = "campaign " + id + " run " + std::to_string(rows.integer(1));
        if (rows.integer(1) < 0 || rows.integer(1) >= campaign.runs)
            throw InputError(path(), 0, where + " is outside this campaign's " + std::to_string(campaign.runs) + " runs");
        r.seed = dem::runSeed(campaign.runSeed, r.run);
        if (rows.integer(2) != static_cast<std::int64_t>(r.seed))
            throw InputError(path(), 0, where + " has seed " + rows.text(2) + ", not this campaign's " + std::to_string(r.seed));
        double* numbers[] = {&r.runoutM, &r.runoutHorizontalM, &r.stopX, &r.stopY, &r.stopZ, &r.energyLineDeg, &r.maxSpeed};
        for (int i = 0; i < 7; ++i) *numbers[i] = rows.real(3 + i);
        r.treeImpacts = static_cast<long>(rows.integer(10));
        r.reason = rows.text(11);
        if (runChecksum(r) != rows.text(12)) {
            notes_.push_back(path() + ": " + where + " fails its checksum (edited or damaged): it is run again");
            damaged.emplace_back(id, r.run);
            continue;
        }
        runs_[c->second][r.run] = r;
    }
    if (damaged.empty()) return;
    SqliteTransaction transaction(*db_);
    auto drop = db_->prepare("DELETE FROM runs WHERE campaign = ? AND run = ?");
    for (const auto& [id, run] : damaged) drop.bind(1, id).bind(2, run).run();
    transaction.commit();
}

void CampaignStore::loadForests() {
    std::map<std::string, std::size_t> index;
    for (std::size_t c = 0; c < plan_.size(); ++c)
        if (plan_[c].forested) index[plan_[c].id] = c;
    auto rows = db_->prepare(
        "SELECT campaign, stems, stems_per_ha, basal_area_m2_ha, mean_dbh_cm, sd_dbh_cm, clark_evans, checksum FROM forests");
    while (rows.step()) {
        const auto c = index.find(rows.text(0));
        if (c == index.end()) throw InputError(path(), 0, "forest statistics of campaign " + rows.text(0) + ", which has no forest in the design");
        ForestSummary s;
        s.stems = static_cast<std::size_t>(rows.integer(1));
        s.stemsPerHa = rows.real(2);
        s.basalAreaM2Ha = rows.real(3);
        s.meanDbhCm = rows.real(4);
        s.sdDbhCm = rows.real(5);
        s.clarkEvans = rows.real(6);
        if (rows.integer(1) < 0 || forestChecksum(s) != rows.text(7)) {
            // Left in place: the summary computed again replaces it.
            notes_.push_back(path() + ": the forest statistics of " + rows.text(0) + " fail their checksum (edited or damaged): computed again");
            continue;
        }
        forests_[c->second] = s;
    }
}

std::vector<int> CampaignStore::missingRuns(std::size_t campaign) const {
    std::vector<int> missing;
    for (int i = 0; i < plan_.at(campaign).runs; ++i)
        if (!runs_[campaign].count(i)) missing.push_back(i);
    return missing;
}

// Prepared once per store, on first use (the tables exist by then), and kept: a campaign stores
// thousands of runs.
SqliteStatement& CampaignStore::statement(std::unique_ptr<SqliteStatement>& slot, const char* sql) {
    if (!slot) slot = std::make_unique<SqliteStatement>(db_->prepare(sql));
    return *slot;
}

void CampaignStore::insertForest(const std::string& campaign, const ForestSummary& s) {
    statement(insertForest_,
              "INSERT OR REPLACE INTO forests (campaign, stems, stems_per_ha, basal_area_m2_ha, mean_dbh_cm, sd_dbh_cm, clark_evans, "
              "checksum) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
        .bind(1, campaign)
        .bind(2, static_cast<std::int64_t>(s.stems))
        .bind(3, s.stemsPerHa)
        .bind(4, s.basalAreaM2Ha)
        .bind(5, s.meanDbhCm)
        .bind(6, s.sdDbhCm)
        .bind(7, s.clarkEvans)
        .bind(8, forestChecksum(s))
        .run();
}

void CampaignStore::save(std::size_t campaign, const RunRecord& r, const ForestSummary* forest) {
    const std::string& id = plan_.at(campaign).id;
    SqliteTransaction transaction(*db_);
    if (forest) insertForest(id, *forest);
    statement(insertRun_,
              "INSERT INTO runs (campaign, run, seed, runout_m, runout_horizontal_m, stop_x_m, stop_y_m, stop_z_m, energy_line_deg, "
              "max_speed_m_s, tree_impacts, reason, checksum) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
        .bind(1, id)
        .bind(2, static_cast<std::int64_t>(r.run))
        .bind(3, static_cast<std::int64_t>(r.seed))
        .bind(4, r.runoutM)
        .bind(5, r.runoutHorizontalM)
        .bind(6, r.stopX)
        .bind(7, r.stopY)
        .bind(8, r.stopZ)
        .bind(9, r.energyLineDeg)
        .bind(10, r.maxSpeed)
        .bind(11, static_cast<std::int64_t>(r.treeImpacts))
        .bind(12, r.reason)
        .bind(13, runChecksum(r))
        .run();
    transaction.commit();
    runs_[campaign][r.run] = r;
    if (forest) forests_[campaign] = *forest;
}

void CampaignStore::saveForest(std::size_t campaign, const ForestSummary& forest) {
    SqliteTransaction transaction(*db_);
    insertForest(plan_.at(campaign).id, forest);
    transaction.commit();
    forests_[campaign] = forest;
}

}  // namespace sylva::assess
