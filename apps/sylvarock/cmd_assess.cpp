// sylvarock assess: protection index PF50 of stands from virtual forests and block campaigns, with
// bootstrap intervals, rankings and correlations (paper Sect. 2.3.3, 3.3; libassess).
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "Cli.hpp"
#include "ProgressBar.hpp"
#include "libassess/Assessment.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libassess/MpiWorld.hpp"
#include "libassess/Report.hpp"
#include "libcommon/InputError.hpp"
#include "libdem/Campaign.hpp"

namespace sylva::cli {
namespace {

// One line on a terminal, redrawn after each run: which campaign, how far, how long left.

// The options, or nothing when --help was asked for.
std::optional<assess::AssessmentOptions> readOptions(int argc, const char* const* argv) {
    po::options_description o("assess");
    std::vector<std::string> stands, sets;
    o.add_options()
        ("stand", po::value(&stands)->composing(), "stand inventory prefix: reads PREFIX_stems.csv and PREFIX_plots.csv (repeatable)")
        ("scene", po::value<std::string>(), "scene INI file without forest (terrain, block, contact laws, release)")
        ("set", po::value(&sets)->composing(), "override a scene key: --set section.key=value (repeatable; e.g. --set stem.parameters=toe2018 for the paper's trees)")
        ("runs", po::value<int>()->default_value(100), "M: block runs per forest realisation")
        ("realisations", po::value<int>()->default_value(5), "K: virtual forests per stand and structure (A and NA)")
        ("baseline-runs", po::value<int>()->default_value(1000), "B: block runs without forest")
        ("model", po::value<std::string>()->default_value("dem"), "dem (the paper's discrete element model) | lumped (its lumped-mass model, docs/lumped.md) | both (the two through the same forests, side by side as the paper's Sect. 3)")
        ("lumped-runs", po::value<int>()->default_value(2000), "lumped-mass model: block runs per forest realisation (a run costs ~0.1 ms)")
        ("lumped-baseline-runs", po::value<int>()->default_value(3000), "lumped-mass model: block runs without forest (the paper's 3 000, Table 1)")
        ("seed", po::value<Seed>()->default_value(Seed{}, "1"), "seed; forests, runs and bootstrap seeds derive from it")
        ("bootstrap", po::value<int>()->default_value(2000), "bootstrap replicates of the PF50 interval")
        ("confidence", po::value<double>()->default_value(0.95, "0.95"), "confidence level of the interval")
        ("threads", po::value<int>()->default_value(0), "worker threads (0: all cores); results do not depend on it")
        ("out", po::value<std::string>(), "output directory: results.json, report/, and campaign.sqlite, every run and forest of the campaign (tables that R, Python and sqlite3 read; docs/assessment.md); must be new or empty")
        ("resume", po::bool_switch(), "continue the campaign in --out: run only what is missing (same options required)");
    po::variables_map vm;
    if (!parse(argc, argv, o, vm,
               "sylvarock assess --stand PREFIX [--stand PREFIX ...] --scene FILE.ini [--set KEY=VALUE ...] --out DIR [--runs M] "
               "[--realisations K] [--baseline-runs B] [--model dem|lumped|both] [--seed S] [--resume]",
               "  sylvarock assess --stand data/stands/GR1 --stand data/stands/PY1 --scene data/scenes/no-forest.ini \\\n"
               "      --runs 100 --realisations 5 --baseline-runs 1000 --seed 4 --out out/assess\n"
               "  (after an interruption, the same command with --resume finishes it)\n"
               "  sylvarock assess --stand data/stands/GR1 --stand data/stands/PY1 --scene data/scenes/no-forest.ini \\\n"
               "      --model both --out out/both     (the DEM and the lumped-mass model side by side: out/both/report/report.md)\n"
               "  mpirun -np 8 sylvarock assess ... --threads 1   (8 MPI ranks, same results; docs/cluster.md)\n"))
        return std::nullopt;
    if (stands.empty()) throw InputError("--stand PREFIX is required (e.g. data/stands/GR1)");
    if (!vm.count("scene")) throw InputError("--scene is required (e.g. data/scenes/no-forest.ini)");
    if (!vm.count("out")) throw InputError("--out DIR is required");
    const double confidence = vm["confidence"].as<double>();
    if (!(confidence > 0 && confidence < 1)) throw InputError("--confidence must be in (0, 1), e.g. 0.95");

    assess::AssessmentOptions a;
    for (const auto& prefix : stands) a.design.stands.push_back(assess::standFromPrefix(prefix));
    a.design.sceneFile = vm["scene"].as<std::string>();
    a.design.sceneOverrides = sets;
    a.design.runs = vm["runs"].as<int>();
    a.design.realisations = vm["realisations"].as<int>();
    a.design.baselineRuns = vm["baseline-runs"].as<int>();
    a.design.seed = vm["seed"].as<Seed>().value;
    a.design.models = assess::parseModels(vm["model"].as<std::string>());
    // A count given for a model the campaign does not run was passed over without a word (--runs 5 with
    // --model lumped ran its 2 000 runs a forest). Said, not refused: a --config file may hold both
    // models' counts.
    for (const auto& [option, model, counterpart] :
         {std::tuple{"runs", dem::Model::Dem, "lumped-runs"}, {"baseline-runs", dem::Model::Dem, "lumped-baseline-runs"},
          {"lumped-runs", dem::Model::Lumped, "runs"}, {"lumped-baseline-runs", dem::Model::Lumped, "baseline-runs"}})
        if (!assess::usesModel(a.design, model) && !vm[option].defaulted())
            std::cerr << "sylvarock assess: warning: --" << option << " counts the " << dem::toString(model) << " model's runs, which --model "
                      << vm["model"].as<std::string>() << " does not make; its runs are counted by --" << counterpart << " ("
                      << vm[counterpart].as<int>() << ")\n";
    a.design.lumpedRuns = vm["lumped-runs"].as<int>();
    a.design.lumpedBaselineRuns = vm["lumped-baseline-runs"].as<int>();
    a.outDir = vm["out"].as<std::string>();
    a.resume = vm["resume"].as<bool>();
    a.threads = threadCount(vm);
    a.bootstrapReplicates = vm["bootstrap"].as<int>();
    a.confidence = confidence;
    return a;
}

int runAssess(int argc, const char* const* argv) {
    const assess::MpiWorld& world = assess::MpiWorld::current();
    // Under mpirun, a bad option is reported once, by rank 0.
    std::optional<assess::AssessmentOptions> read = world.agreeOn([&] { return readOptions(argc, argv); });
    if (!read) return 0;
    assess::AssessmentOptions& a = *read;
    if (!world.coordinator()) {
        assess::serveAssessment(a);
        return 0;
    }
    a.onNote = [](const std::string& text) { std::cerr << "sylvarock assess: " << text << "\n"; };
    ProgressBar progress(stderrIsTerminal());
    a.onRunDone = [&progress](const std::string& campaign, int done, int total) { progress.update(done, total, campaign); };

    const auto t0 = std::chrono::steady_clock::now();
    a.writeOutputs = [&a](const std::vector<assess::AssessmentResults>& results) {
        assess::writeResultsJson(a.outDir + "/results.json", results);
        const assess::FigureSet figures = assess::writeReport(a.outDir + "/report", results);
        if (!figures.warning.empty()) std::cerr << "sylvarock assess: warning: " << figures.warning << "\n";
    };
    std::vector<assess::AssessmentResults> results;
    try {
        results = assess::runAssessment(a);
    } catch (const assess::CampaignWithoutFinishedRuns& e) {
        std::cerr << "sylvarock assess: error: " << e.what() << "\n";
        return kRunsFailed;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::size_t failed = 0;
    for (const auto& model : results) {
        const std::string name = results.size() > 1 ? dem::toString(model.model) + ": " : "";
        std::printf("%sno forest: Dist50 %.1f m (%zu runs)\n", name.c_str(), model.baselineDist50, model.baseline.size());
        for (const auto& r : model.stands)
            std::printf("%s%-8s %-2s PF50 %.3f [%.3f, %.3f]  Dist50 %.1f m  rank %d  (G %.1f m2/ha)\n", name.c_str(), r.name.c_str(),
                        assess::structureCode(r.structure).c_str(), r.pf50, r.pf50Ci.low, r.pf50Ci.high, r.dist50, r.rankPf50,
                        r.inventory.basalAreaM2Ha);
        failed += model.failedRuns.size();
    }
    std::printf("results in %s/results.json, report in %s/report/report.md (%.1f s)\n", a.outDir.c_str(), a.outDir.c_str(), wall);
    if (failed) {
        std::cerr << "sylvarock assess: " << failed << " run(s) stopped on a numerical error and are left out (results.json failed_runs)\n";
        return kRunsFailed;
    }
    return 0;
}

const CommandRegistration reg{{4, "assess", "protection index PF50 of stands with intervals, ranks and correlations", &runAssess, true}};

}  // namespace
}  // namespace sylva::cli
