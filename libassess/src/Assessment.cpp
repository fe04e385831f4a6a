#include "libassess/Assessment.hpp"

#include <memory>

#include "libassess/CampaignRunner.hpp"
#include "libdem/SceneConfig.hpp"
#include "libstand/InputError.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/StandCatalogue.hpp"
#include "libstand/StandStatistics.hpp"

namespace sylva::assess {

AssessmentResults runAssessment(const AssessmentOptions& options) {
    const auto note = [&](const std::string& text) {
        if (options.onNote) options.onNote(text);
    };
    const AssessmentDesign& design = options.design;
    validate(design);
    if (options.bootstrapReplicates < 100)
        throw InputError("--bootstrap must be at least 100 replicates, got " + std::to_string(options.bootstrapReplicates));
    if (options.outDir.empty()) throw InputError("--out DIR is required");

    dem::SceneConfig sceneConfig = dem::loadScene(design.sceneFile, design.sceneOverrides);
    if (!sceneConfig.forestFile.empty())
        throw InputError(design.sceneFile, 0, "the scene places a forest (" + sceneConfig.forestFile +
                                                  "); assess generates its own forests: give a scene without one");
    std::vector<stand::StandCatalogue> catalogues;
    std::vector<ForestSummary> inventories;
    for (const auto& s : design.stands) {
        stand::Inventory inventory = stand::readInventory(s.stemsCsv, s.plotsCsv);
        inventory.name = s.name;
        for (const auto& w : inventory.warnings) note("stand " + s.name + ": warning: " + w);
        inventories.push_back(summariseInventory(stand::standStatistics(inventory), inventory.hasDiameters));
        catalogues.emplace_back(inventory, s.stemsCsv);
    }
    const auto bareScene = std::make_shared<const dem::Scene>(std::move(sceneConfig));
    forestExtent(*bareScene);  // refuses a terrain without room for a forest before anything is written

    const std::vector<Campaign> plan = planCampaigns(design);
    CampaignStore store(options.outDir, design, plan, options.resume);
    for (const auto& n : store.notes()) note(n);
    int stored = 0, total = 0;
    for (std::size_t c = 0; c < plan.size(); ++c) {
        stored += static_cast<int>(store.log(c).records().size());
        total += plan[c].runs;
    }
    note((store.resumed() ? "resuming: " : "new campaign: ") + std::to_string(stored) + " of " + std::to_string(total) +
         " runs stored in " + options.outDir + ", " + std::to_string(total - stored) + " to run");

    RunnerSettings runner;
    runner.threads = options.threads;
    runner.onRunDone = options.onRunDone;
    runner.onRunFailed = [&options](const std::string& campaign, const dem::RunResult& r) {
        if (options.onNote)
            options.onNote("warning: " + campaign + " run " + std::to_string(r.run) + " (seed " + std::to_string(r.seed) +
                           ") stopped on a numerical error and is left out: " + r.failure);
    };
    const std::size_t notesBefore = store.notes().size();
    runMissing(plan, store, bareScene, catalogues, runner);
    for (std::size_t n = notesBefore; n < store.notes().size(); ++n) note(store.notes()[n]);

    BootstrapSettings bootstrap;
    bootstrap.replicates = options.bootstrapReplicates;
    bootstrap.confidence = options.confidence;
    AssessmentResults results = analyse(design, plan, store, inventories, bootstrap);
    const auto& soil = bareScene->soil();
    results.terrainXmin = soil.xmin();
    results.terrainXmax = soil.xmax();
    results.terrainYmin = soil.ymin();
    results.terrainYmax = soil.ymax();
    results.forestStartX = forestExtent(*bareScene).lower().x();
    return results;
}

}  // namespace sylva::assess
