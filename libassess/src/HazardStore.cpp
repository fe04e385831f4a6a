#include "HazardStore.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "libcommon/BuildId.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

namespace {
// A transaction per 64 runs or per 5 s, whichever comes first: a commit costs a disk sync, a kill
// loses at most the runs since the last one (seconds of DEM runs, not minutes).
constexpr std::size_t kBatch = 64;
constexpr auto kBatchTime = std::chrono::seconds(5);
}  // namespace

HazardStore::HazardStore(const std::string& path, bool create) : db_(path, create) {}

std::unique_ptr<HazardStore> HazardStore::create(const std::string& path, const std::vector<std::string>& fingerprint) {
    std::unique_ptr<HazardStore> s(new HazardStore(path, true));
    s->db_.execute("CREATE TABLE inputs (line INTEGER PRIMARY KEY, text TEXT NOT NULL);"
                   "CREATE TABLE runs (pass TEXT NOT NULL, run INTEGER NOT NULL, failed INTEGER NOT NULL, record BLOB, PRIMARY KEY (pass, run));");
    SqliteTransaction t(s->db_);
    SqliteStatement insert = s->db_.prepare("INSERT INTO inputs (line, text) VALUES (?, ?)");
    for (std::size_t i = 0; i < fingerprint.size(); ++i) insert.bind(1, static_cast<std::int64_t>(i)).bind(2, fingerprint[i]).run();
    t.commit();
    return s;
}

std::unique_ptr<HazardStore> HazardStore::resume(const std::string& path, const std::vector<std::string>& fingerprint) {
    if (!std::filesystem::is_regular_file(path))
        throw InputError(path, 0, "--resume: no hazard store here (a map started by sylvarock hazard keeps one in OUT/hazard.sqlite)");
    std::unique_ptr<HazardStore> s(new HazardStore(path, false));
    std::vector<std::string> stored;
    SqliteStatement read = s->db_.prepare("SELECT text FROM inputs ORDER BY line");
    while (read.step()) stored.push_back(read.text(0));
    s->note_ = otherBuildNote(path, stored, "map");
    // The build is said, not compared (a note above): the inputs are.
    const auto inputs = [](std::vector<std::string> lines) {
        lines.erase(std::remove_if(lines.begin(), lines.end(), [](const std::string& l) { return l.rfind("# ", 0) == 0; }), lines.end());
        return lines;
    };
    stored = inputs(stored);
    const std::vector<std::string> wanted = inputs(fingerprint);
    for (std::size_t i = 0; i < std::max(stored.size(), wanted.size()); ++i) {
        const std::string was = i < stored.size() ? stored[i] : "(nothing)", now = i < wanted.size() ? wanted[i] : "(nothing)";
        if (was != now)
            throw InputError(path, 0, "--resume with other inputs: the map was started with '" + was + "', this command gives '" + now +
                                          "': resume with the same command, or start a new map in another --out");
    }
    return s;
}

std::map<long, HazardStore::Finished> HazardStore::finished(const std::string& pass) {
    std::map<long, Finished> runs;
    SqliteStatement read = db_.prepare("SELECT run, failed, record FROM runs WHERE pass = ?");
    read.bind(1, pass);
    while (read.step()) runs[static_cast<long>(read.integer(0))] = {read.integer(1) != 0, read.blob(2)};
    return runs;
}

void HazardStore::save(const std::string& pass, long run, bool failed, std::string record) {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back({pass, run, failed, std::move(record)});
    if (pending_.size() >= kBatch || std::chrono::steady_clock::now() - lastWrite_ >= kBatchTime) writeBatch();
}

void HazardStore::flush() {
    std::lock_guard<std::mutex> lock(mutex_);
    writeBatch();
}

void HazardStore::writeBatch() {
    if (pending_.empty()) return;
    SqliteTransaction t(db_);
    SqliteStatement insert = db_.prepare("INSERT OR REPLACE INTO runs (pass, run, failed, record) VALUES (?, ?, ?, ?)");
    for (const auto& p : pending_)
        insert.bind(1, p.pass).bind(2, static_cast<std::int64_t>(p.run)).bind(3, static_cast<std::int64_t>(p.failed)).bindBlob(4, p.record).run();
    t.commit();
    pending_.clear();
    lastWrite_ = std::chrono::steady_clock::now();
}

}  // namespace sylva::assess
