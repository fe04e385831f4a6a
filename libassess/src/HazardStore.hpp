#pragma once
// What a hazard map has run so far, kept in OUT/hazard.sqlite as each run ends, so that an interrupted
// map (a killed process, a full disk, a cluster's time limit) resumes where it stopped with --resume
// and gives the maps it would have given uninterrupted. The inputs' fingerprint is stored with it: a
// resume with other inputs is refused, naming what changed.
#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "SqliteDatabase.hpp"

namespace sylva::assess {

class HazardStore {
public:
    // `fingerprint`: one line per input ("dtm: PATH HASH", "seed: 4", ...). create() starts a new
    // store; resume() opens the existing one and throws InputError naming the first line that differs.
    // Lines starting with "# " (the build that made the runs) are not compared: one that differs is
    // kept in note(), to be said.
    static std::unique_ptr<HazardStore> create(const std::string& path, const std::vector<std::string>& fingerprint);
    static std::unique_ptr<HazardStore> resume(const std::string& path, const std::vector<std::string>& fingerprint);

    struct Finished {
        bool failed = false;
        std::string record;  // the run's results, as HazardRun encodes them (empty for a failed run)
    };
    std::map<long, Finished> finished(const std::string& pass);
    // Thread-safe; written in batches (a transaction per 64 runs or 5 s), the rest by flush().
    void save(const std::string& pass, long run, bool failed, std::string record);
    void flush();
    const std::string& note() const { return note_; }

private:
    explicit HazardStore(const std::string& path, bool create);
    void writeBatch();  // under mutex_
    SqliteDatabase db_;
    std::mutex mutex_;
    struct Pending {
        std::string pass;
        long run;
        bool failed;
        std::string record;
    };
    std::vector<Pending> pending_;
    std::string note_;
    std::chrono::steady_clock::time_point lastWrite_ = std::chrono::steady_clock::now();
};

}  // namespace sylva::assess
