#include "libassess/Assessment.hpp"

#include <exception>
#include <functional>
#include <memory>

#include "libassess/CampaignRunner.hpp"
#include "libassess/CampaignStore.hpp"
#include "libassess/MpiWorld.hpp"
#include "libdem/BlockRun.hpp"
#include "libdem/SceneConfig.hpp"
#include "libdem/TreeField.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/StandCatalogue.hpp"
#include "libstand/StandStatistics.hpp"

namespace sylva::assess {

namespace {

// What every rank reads from the inputs, the same on each.
struct Inputs {
    std::vector<stand::StandCatalogue> catalogues;
    std::vector<ForestSummary> inventories;
    std::shared_ptr<const dem::Scene> bareScene;
    std::vector<Campaign> plan;
};

Inputs readInputs(const AssessmentOptions& options, const std::function<void(const std::string&)>& note) {
    const AssessmentDesign& design = options.design;
    validate(design);
    if (options.bootstrapReplicates < 100)
        throw InputError("--bootstrap must be at least 100 replicates, got " + std::to_string(options.bootstrapReplicates));
    if (options.outDir.empty()) throw InputError("--out DIR is required");
    // A PF50 from a handful of runs came with an interval of zero width ([0.740, 0.740] from one run),
    // which reads as certainty: the bootstrap resamples only the runs there are.
    constexpr long kFewRuns = 100;  // the paper's design: 100 runs per stand and structure
    for (const dem::Model model : design.models) {
        const long forested = static_cast<long>(runsPerRealisation(design, model)) * design.realisations;
        const long bare = baselineRuns(design, model);
        if (forested < kFewRuns || bare < kFewRuns)
            note("warning: " + dem::toString(model) + ": each PF50 rests on " + std::to_string(forested) +
                 " forested run(s) and " + std::to_string(bare) + " without forest: its interval shows only the spread of "
                 "these few, not the sampling error (100 or more of each, as the paper's design)");
    }

    dem::SceneConfig sceneConfig = dem::loadScene(design.sceneFile, design.sceneOverrides);
    if (!sceneConfig.forestFile.empty())
        throw InputError(design.sceneFile, 0, "the scene places a forest (" + sceneConfig.forestFile +
                                                  "); assess generates its own forests: give a scene without one");
    Inputs in;
    for (const auto& s : design.stands) {
        stand::Inventory inventory = stand::readInventory(s.stemsCsv, s.plotsCsv);
        inventory.name = s.name;
        dem::requireBuildableStems(inventory, s.stemsCsv, sceneConfig.stem.tipDiameter);  // before the store is made
        for (const auto& w : inventory.warnings) note("stand " + s.name + ": warning: " + w);
        // Its forests draw their density, diameters and aggregation from these stems alone.
        constexpr std::size_t kFewStems = 10;
        if (inventory.stems.size() < kFewStems)
            note("stand " + s.name + ": warning: its inventory holds " + std::to_string(inventory.stems.size()) +
                 " stem(s): its forests' density, diameters and aggregation rest on them alone, and its PF50 with them");
        in.inventories.push_back(summariseInventory(stand::standStatistics(inventory), inventory.hasDiameters));
        in.catalogues.emplace_back(inventory, s.stemsCsv);
    }
    in.bareScene = std::make_shared<const dem::Scene>(std::move(sceneConfig));
    forestExtent(*in.bareScene);  // refuses a terrain without room for a forest before anything is written
    in.plan = planCampaigns(design);
    return in;
}

// A block stopped by stop.max_time_s or at the terrain's end would have gone further: its run-out is
// a lower bound, and so are the Dist50 and PF50 built on such runs. simulate says so; assess did not,
// and gave a PF50 of -0.100 from runs that had all hit the time limit.
void noteUnfinishedRuns(const AssessmentDesign& design, const std::vector<Campaign>& plan, const CampaignStore& store,
                        const std::function<void(const std::string&)>& note) {
    const std::string timeLimit = dem::toString(dem::StopReason::TimeLimit), leftDomain = dem::toString(dem::StopReason::LeftDomain),
                      failed = dem::toString(dem::StopReason::Failed);
    for (const dem::Model model : design.models) {
        long timed = 0, left = 0, finished = 0;
        for (std::size_t c = 0; c < plan.size(); ++c) {
            if (plan[c].model != model) continue;
            for (const auto& [run, r] : store.runs(c)) {
                timed += r.reason == timeLimit;
                left += r.reason == leftDomain;
                finished += r.reason != failed;
            }
        }
        if (timed + left == 0) continue;
        std::string which;
        if (timed) which = std::to_string(timed) + " reached the time limit still moving (stop.max_time_s)";
        if (left) which += (timed ? " and " : "") + std::to_string(left) + " left the terrain";
        note("warning: " + dem::toString(model) + ": of " + std::to_string(finished) + " runs, " + which +
             ": their run-outs are where they were cut, lower bounds, and the Dist50 and PF50 that count them are too "
             "(stop_reasons in results.json, each run's in report/runs.csv; a longer time limit or slope would tell)");
    }
}

}  // namespace

std::vector<AssessmentResults> runAssessment(const AssessmentOptions& options) {
    const auto note = [&](const std::string& text) {
        if (options.onNote) options.onNote(text);
    };
    Inputs in;
    const std::unique_ptr<CampaignStore> opened = MpiWorld::current().agreeOn([&] {
        in = readInputs(options, note);
        return std::make_unique<CampaignStore>(options.outDir, options.design, in.plan, options.resume);
    });
    CampaignStore& store = *opened;
    const std::vector<Campaign>& plan = in.plan;
    for (const auto& n : store.notes()) note(n);
    int stored = 0, total = 0;
    for (std::size_t c = 0; c < plan.size(); ++c) {
        stored += static_cast<int>(store.runs(c).size());
        total += plan[c].runs;
    }
    note((store.resumed() ? "resuming: " : "new campaign: ") + std::to_string(stored) + " of " + std::to_string(total) +
         " runs stored in " + options.outDir + ", " + std::to_string(total - stored) + " to run");

    RunnerSettings runner;
    runner.threads = options.threads;
    runner.onRunDone = options.onRunDone;
    runner.onRunFailed = [&note](const std::string& campaign, const RunRecord& r, const std::string& why) {
        note("warning: " + campaign + " run " + std::to_string(r.run) + " (seed " + std::to_string(r.seed) +
             ") stopped on a numerical error and is left out: " + why);
    };
    const std::size_t notesBefore = store.notes().size();
    runMissing(plan, store, in.bareScene, in.catalogues, runner);
    for (std::size_t n = notesBefore; n < store.notes().size(); ++n) note(store.notes()[n]);
    noteUnfinishedRuns(options.design, plan, store, note);

    BootstrapSettings bootstrap;
    bootstrap.replicates = options.bootstrapReplicates;
    bootstrap.confidence = options.confidence;
    std::vector<AssessmentResults> all;
    for (auto model : options.design.models) {
        AssessmentResults results = analyse(options.design, model, plan, store, in.inventories, bootstrap);
        const auto& soil = in.bareScene->soil();
        results.terrainXmin = soil.xmin();
        results.terrainXmax = soil.xmax();
        results.terrainYmin = soil.ymin();
        results.terrainYmax = soil.ymax();
        results.forestStartX = forestExtent(*in.bareScene).lower().x();
        all.push_back(std::move(results));
    }
    if (options.writeOutputs) options.writeOutputs(all);
    return all;
}

void serveAssessment(const AssessmentOptions& options) {
    const Inputs in = MpiWorld::current().agreeOn([&] { return readInputs(options, [](const std::string&) {}); });
    RunnerSettings runner;
    runner.threads = options.threads;
    serveCampaigns(in.plan, in.bareScene, in.catalogues, runner);
}

}  // namespace sylva::assess
