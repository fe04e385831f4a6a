// The campaign store as --resume opens it, after arbitrary SQL edits (the input, run on a store of a
// small campaign with a few runs and a forest): types changed, NULLs, rows added, removed or out of
// range, tables dropped. Opening must refuse with InputError or drop what fails its checksum; what it
// keeps must be the campaign's.
#include <sqlite3.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "FuzzFile.hpp"
#include "libassess/CampaignStore.hpp"
#include "libdem/Campaign.hpp"
#include "libcommon/InputError.hpp"

namespace {
using namespace sylva::assess;
namespace fs = std::filesystem;

AssessmentDesign design() {
    AssessmentDesign d;
    d.stands.push_back(standFromPrefix(std::string(SYLVAROCK_DATA) + "/stands/GR1"));
    d.sceneFile = std::string(SYLVAROCK_DATA) + "/scenes/no-forest.ini";
    d.runs = 3;
    d.realisations = 1;
    d.baselineRuns = 2;
    return d;
}

// The pristine store, made once: two runs of the baseline, one of GR1_A_001 with its forest. Its
// files are kept in memory and written out for each input: fs::copy's copy_file_range/sendfile fail
// with EINTR when libFuzzer's -timeout alarm lands, and an ofstream retries its writes.
using StoreFiles = std::vector<std::pair<std::string, std::string>>;  // file name, contents

const StoreFiles& pristine() {
    static const StoreFiles files = [] {
        const fs::path d = sylva::fuzz::scratch() / "pristine";
        fs::remove_all(d);
        {  // closed before its files are read
            const auto plan = planCampaigns(design());
            CampaignStore store(d.string(), design(), plan, false);
            RunRecord r;
            r.reason = "rest";
            for (int run : {0, 1}) {
                r.run = run;
                r.seed = sylva::dem::runSeed(plan[0].runSeed, run);
                r.runoutM = 100 + run;
                store.save(0, r);
            }
            r.run = 0;
            r.seed = sylva::dem::runSeed(plan[1].runSeed, 0);
            ForestSummary f;
            f.stems = 10;
            f.clarkEvans = 0.8;
            store.save(1, r, &f);
        }
        StoreFiles kept;
        for (const auto& entry : fs::directory_iterator(d)) {
            std::ifstream in(entry.path(), std::ios::binary);
            kept.emplace_back(entry.path().filename().string(), std::string(std::istreambuf_iterator<char>(in), {}));
        }
        return kept;
    }();
    return files;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const fs::path dir = sylva::fuzz::scratch() / "store";
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& [name, contents] : pristine()) std::ofstream(dir / name, std::ios::binary) << contents;
    sqlite3* db = nullptr;
    if (sqlite3_open((dir / CampaignStore::kFileName).c_str(), &db) == SQLITE_OK)
        sqlite3_exec(db, sylva::fuzz::text(data, size).c_str(), nullptr, nullptr, nullptr);  // errors are fine: a partial edit
    sqlite3_close(db);
    try {
        const auto plan = planCampaigns(design());
        CampaignStore store(dir.string(), design(), plan, true);
        for (std::size_t c = 0; c < plan.size(); ++c)
            for (const auto& [run, record] : store.runs(c))
                if (run < 0 || run >= plan[c].runs || record.seed != sylva::dem::runSeed(plan[c].runSeed, run)) std::abort();
    } catch (const sylva::InputError&) {
    }
    return 0;
}
