// The campaign store as --resume opens it, after arbitrary SQL edits (the input, run on a store of a
// small campaign with a few runs and a forest): types changed, NULLs, rows added, removed or out of
// range, tables dropped. Opening must refuse with InputError or drop what fails its checksum; what it
// keeps must be the campaign's.
#include <sqlite3.h>

#include <cstdlib>
#include <filesystem>

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

// The pristine store, made once: two runs of the baseline, one of GR1_A_001 with its forest.
const fs::path& pristine() {
    static const fs::path dir = [] {
        const fs::path d = sylva::fuzz::scratch() / "pristine";
        fs::remove_all(d);
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
        return d;
    }();
    return dir;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const fs::path dir = sylva::fuzz::scratch() / "store";
    fs::remove_all(dir);
    fs::copy(pristine(), dir, fs::copy_options::recursive);
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
