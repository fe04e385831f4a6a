// sylvarock simulate: Monte Carlo block runs on a scene; per-run table, summary, figures.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include "Cli.hpp"
#include "ProgressBar.hpp"
#include "Gnuplot.hpp"
#include "libassess/MpiWorld.hpp"
#include "libassess/RankedCampaign.hpp"
#include "libdem/BlockShape.hpp"
#include "libdem/Campaign.hpp"
#include "libdem/CampaignSummary.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::cli {
namespace {

// The cumulative run-out distribution and the map of stop positions (as the paper's Fig. 8).
void drawFigures(const std::string& dir, const dem::Scene& scene, const std::vector<dem::RunResult>& runs) {
    std::vector<double> runout;
    for (const auto& r : runs) runout.push_back(r.runoutAlongSlope);
    std::sort(runout.begin(), runout.end());
    {
        std::ofstream cdf(dir + "/runout_cdf.csv");
        cdf << "runout_m,share_stopped\n";
        for (std::size_t i = 0; i < runout.size(); ++i) cdf << runout[i] << ',' << (i + 1.0) / runout.size() << '\n';
    }
    std::ostringstream gp;
    gp << "set datafile separator ','\nset terminal svg size 800,500 dynamic\nset grid\nunset key\n"
       << "set yrange [0:1.02]\n";
    // One run (a single-tree impact) or runs that all stop at one place: give the axis a width.
    if (!runout.empty() && runout.front() == runout.back())
        gp << "set xrange [" << runout.front() - 1 << ":" << runout.back() + 1 << "]\n";
    gp << "set output " << gnuplotText(dir + "/runout_cdf.svg") << "\nset title 'Cumulative distribution of run-out'\n"
       << "set xlabel 'run-out along the slope (m)'\nset ylabel 'share of blocks stopped'\n"
       << "plot " << gnuplotText(dir + "/runout_cdf.csv") << " every ::1 using 1:2 with steps lw 2\n"
       << "set output " << gnuplotText(dir + "/stop_map.svg") << "\nset title 'Stop positions'\nset xlabel 'x (m)'\nset ylabel 'y (m)'\n"
       << "set xrange [" << scene.soil().xmin() << ":" << scene.soil().xmax() << "]\nset yrange [" << scene.soil().ymin()
       << ":" << scene.soil().ymax() << "]\nset size ratio -1\n"
       << "plot " << gnuplotText(dir + "/runs.csv") << " every ::1 using 6:7 with points pt 7 ps 0.5\n";
    plotWithGnuplot(gp.str(), "run-out figures");
}


// The files a simulate run writes (and its trajectories/ folder). An earlier run's are removed before a
// new one writes, so that the folder never mixes two runs (a forested run's impacts.csv and figures
// beside a bare run's runs.csv were left as they were). An earlier run is known by its runs.csv; files
// of these names without it are someone else's, and another command's folder is refused too: simulate
// would overwrite them (it once deleted a user's summary.json and trajectories/ in --out .).
const char* const kSimulateOutputs[] = {"runs.csv",       "summary.json",   "impacts.csv",  "energy.json",
                                        "runout_cdf.csv", "runout_cdf.svg", "stop_map.svg", "trajectories"};

void prepareOutFolder(const std::string& dir) {
    namespace fs = std::filesystem;
    if (fs::exists(dir) && !fs::is_directory(dir)) throw InputError("--out " + dir + " is a file, not a folder");
    const auto refuse = [&](const std::string& what) {
        throw InputError("--out " + dir + " holds " + what + ": simulate would overwrite it; give simulate a folder of its own");
    };
    for (const auto& [store, command] : {std::pair{"campaign.sqlite", "assess"}, std::pair{"hazard.sqlite", "hazard"}})
        if (fs::exists(fs::path(dir) / store)) refuse(std::string("a sylvarock ") + command + " result (" + store + ")");
    const bool earlierRun = dem::isRunsCsv((fs::path(dir) / "runs.csv").string());
    bool replaced = false;
    for (const std::string name : kSimulateOutputs) {
        const fs::path path = fs::path(dir) / name;
        if (!fs::exists(path)) continue;
        if (!earlierRun)
            refuse(name == "runs.csv" ? std::string("a runs.csv that simulate did not write (or an older build, with other columns)")
                                      : name + (name == "trajectories" ? "/" : "") + ", and no runs.csv of an earlier simulate run beside it");
        replaced = (name == "trajectories" ? dem::removeTrajectories(path.string()) : fs::remove(path)) || replaced;
    }
    if (replaced) std::cerr << "--out " << dir << ": the earlier simulate run's outputs are replaced\n";
    fs::create_directories(dir);
}

// What simulate runs, read from its options (every MPI rank reads the same).
struct Simulation {
    std::string sceneFile, out;
    bool figures = true;
    std::unique_ptr<const dem::Scene> scene;
    dem::CampaignOptions campaign;
};

// The simulation, or nothing when help was asked for. Only rank 0 prepares the output folder.
std::optional<Simulation> readSimulation(int argc, const char* const* argv) {
    po::options_description o("simulate");
    std::vector<std::string> sets;
    o.add_options()
        ("scene", po::value<std::string>(), "scene INI file (terrain, block, contact laws, release, stop); defaults are the paper's Table 2")
        ("model", po::value<std::string>()->default_value("dem"), "dem (the paper's discrete element model) | lumped (its lumped-mass model after Rockyfor3D, thousands of runs per second; docs/lumped.md)")
        ("runs", po::value<int>(), "number of block runs (default 100; 1 for a single-tree launch)")
        ("seed", po::value<Seed>()->default_value(Seed{}, "1"), "campaign seed; run i uses a seed derived from (seed, i)")
        ("threads", po::value<int>()->default_value(0), "worker threads (0: all cores); results do not depend on it")
        ("out", po::value<std::string>(), "output directory (runs.csv, summary.json, impacts.csv, figures; a single-tree launch also energy.json: where the block's energy went, the tree's terms, each break with its time, height and diameter; docs/model-stems.md)")
        ("forest", po::value<std::string>(), kForestHelp)
        ("trajectory", po::bool_switch(), "also write sampled trajectories (CSV and VTK) to OUT/trajectories/")
        ("block", po::value<std::string>(), "block shape override: cube | cuboid | sphere")
        ("set", po::value(&sets)->composing(), "override a scene key: --set section.key=value (repeatable)")
        ("only-run", po::value<std::vector<int>>()->composing(), "run only this run of the campaign, seeded as in the whole one (repeatable; numbered as in runs.csv and the error messages): to look again at a run that stopped")
        ("no-figures", po::bool_switch(), "do not draw the SVG figures")
        ("help-scene", po::bool_switch(), "list every scene key with its default and meaning");
    po::variables_map vm;
    if (!parse(argc, argv, o, vm, "sylvarock simulate --scene FILE.ini --runs N --seed S --out DIR [options]",
               "  sylvarock simulate --scene data/scenes/no-forest.ini --runs 100 --seed 1 --out out/no-forest\n"
               "  sylvarock simulate --scene data/scenes/no-forest.ini --runs 4 --trajectory --block sphere --out out/t\n"
               "  sylvarock simulate --scene data/scenes/no-forest.ini --set soil.friction_deg=35 --out out/phi35\n"
               "  sylvarock simulate --scene data/scenes/no-forest.ini --model lumped --runs 60000 --out out/lumped\n"
               "  sylvarock simulate --scene data/scenes/single-tree.ini --set tree.dbh_cm=20 --set block.speed_m_s=10 --out out/tree\n"
               "  mpirun -np 8 sylvarock simulate ... --threads 1   (8 MPI ranks, same results; docs/cluster.md)\n"))
        return std::nullopt;
    if (vm["help-scene"].as<bool>()) {
        std::cout << dem::describeSceneKeys() << "\n";
        return std::nullopt;
    }
    if (!vm.count("scene")) throw InputError("--scene is required (e.g. data/scenes/no-forest.ini)");
    if (!vm.count("out")) throw InputError("--out DIR is required");
    const dem::Model model = dem::parseModel(vm["model"].as<std::string>());  // before the scene is built
    if (vm.count("block")) {
        try {
            dem::parseBlockShape(vm["block"].as<std::string>());  // named as the user typed it, not as the --set it becomes
        } catch (const InputError& e) {
            throw InputError(std::string("--block: ") + e.what());
        }
        sets.insert(sets.begin(), "block.shape=" + vm["block"].as<std::string>());
    }
    applyForestOption(vm, sets);
    const int runs = vm.count("runs") ? vm["runs"].as<int>() : -1;
    if (vm.count("runs") && runs < 1) throw InputError("--runs must be at least 1");

    Simulation sim;
    sim.sceneFile = vm["scene"].as<std::string>();
    sim.out = vm["out"].as<std::string>();
    sim.figures = !vm["no-figures"].as<bool>();
    sim.scene = std::make_unique<const dem::Scene>(dem::loadScene(sim.sceneFile, sets));
    dem::CampaignOptions& c = sim.campaign;
    c.runs = runs > 0 ? runs : (sim.scene->config().launch.enabled ? 1 : 100);
    c.model = model;
    if (c.model == dem::Model::Lumped && sim.scene->config().launch.enabled)
        throw InputError("--model lumped follows blocks down a slope; a single-tree launch (block.speed_m_s) needs the DEM");
    c.seed = vm["seed"].as<Seed>().value;
    if (vm.count("only-run"))
        for (const int i : vm["only-run"].as<std::vector<int>>()) {
            if (i < 0 || i >= c.runs)
                throw InputError("--only-run " + std::to_string(i) + ": the campaign's runs are numbered 0 to " +
                                 std::to_string(c.runs - 1) + " (--runs " + std::to_string(c.runs) + ")");
            if (std::find(c.only.begin(), c.only.end(), i) != c.only.end())
                throw InputError("--only-run " + std::to_string(i) + " is given twice: its row would count twice in the statistics");
            c.only.push_back(i);
        }
    c.threads = threadCount(vm);
    c.run.recordTrajectory = vm["trajectory"].as<bool>();
    c.run.recordBreaks = sim.scene->config().launch.enabled;  // energy.json lists the struck stem's
    if (assess::MpiWorld::current().coordinator()) prepareOutFolder(sim.out);  // once every option has been read
    return sim;
}

int runSimulate(int argc, const char* const* argv) {
    const auto t0 = std::chrono::steady_clock::now();
    const assess::MpiWorld& world = assess::MpiWorld::current();
    // Under mpirun, a bad option is reported once, by rank 0.
    std::optional<Simulation> read = world.agreeOn([&] { return readSimulation(argc, argv); });
    if (!read) return 0;
    const dem::Scene& scene = *read->scene;
    dem::CampaignOptions& c = read->campaign;
    const std::string& out = read->out;
    if (!world.coordinator()) {
        assess::runCampaignOnRanks(scene, c);
        return 0;
    }
    std::cerr << "scene: " << scene.soil().size() << " soil spheres over x [" << scene.soil().xmin() << ", "
              << scene.soil().xmax() << "] m; block " << dem::toString(scene.config().block.shape) << " of "
              << scene.blockTemplate().mass() << " kg";
    if (scene.forested()) std::cerr << "; forest of " << scene.forest().trees.size() << " stems";
    if (world.size() > 1) std::cerr << "; runs spread over " << world.size() << " MPI ranks";
    std::cerr << "\n";
    ProgressBar bar(stderrIsTerminal());
    c.onRunDone = [&bar](const dem::RunResult&, int done, int total) { bar.update(done, total); };
    const auto results = assess::runCampaignOnRanks(scene, c);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const auto s = dem::summarise(results);
    dem::writeRunsCsv(out + "/runs.csv", results);
    dem::writeSummaryJson(out + "/summary.json", s, wall, read->sceneFile, dem::toString(c.model));
    if (scene.forested()) dem::writeImpactsCsv(out + "/impacts.csv", results);
    if (scene.config().launch.enabled) {
        dem::writeImpactEnergyJson(out + "/energy.json", results.front());
        // A launch above the tree or wide of it passes by: energy.json then holds no impact to read.
        const dem::RunResult& r = results.front();
        if (r.reason != dem::StopReason::Failed && r.impacts.empty()) {
            const auto& l = scene.config().launch;
            std::ostringstream os;
            os.precision(3);
            os << "the block passed the tree without touching it (block.impact_height_m " << l.impactHeight << " m on a stem "
               << scene.trees().tree(0).geometry.height << " m tall, block.eccentricity " << l.eccentricity << "): energy.json holds no impact";
            std::cerr << "sylvarock simulate: warning: " << os.str() << "\n";
        }
    }
    if (c.run.recordTrajectory) dem::writeTrajectories(out + "/trajectories", results);
    if (read->figures) drawFigures(out, scene, results);

    std::printf("%d %s runs in %.1f s wall (median %.3f s CPU per run)\n", s.runs, dem::toString(c.model).c_str(), wall, s.cpu50);
    if (s.failedRuns < s.runs) {
        std::printf("run-out along the slope: Dist50 %.1f m (p10 %.1f, p90 %.1f); horizontal %.1f m\n", s.dist50,
                    s.runoutQuantiles.at(10), s.runoutQuantiles.at(90), s.horizontal50);
        std::printf("energy line %.1f deg (%.1f-%.1f); lateral sd %.1f m; speed median %.1f m/s (max %.1f); "
                    "bounce <= 1 m in %.0f %% of runs\n",
                    s.energyLine50, s.energyLineMin, s.energyLineMax, s.lateralSd, s.meanSpeed50, s.maxSpeed50,
                    100 * s.shareBounceBelow1m);
    }
    for (const auto& [k, v] : s.stopReasons) std::printf("stopped by %s: %d\n", k.c_str(), v);
    if (c.model == dem::Model::Dem)  // the lumped model has no energy audit: its losses are its restitutions
        std::printf("energy budget: worst imbalance %.2f %%; %d run(s) above integration.energy_warning (%.0f %%)%s\n",
                    100 * s.worstEnergyImbalance, s.energyFlaggedRuns, 100 * scene.config().integration.energyWarning,
                    s.energyFlaggedRuns > 0 ? ": flagged in runs.csv (energy_flag), rerun them with a smaller integration.safety" : "");
    // A forest's energies are megajoules, a single tree's kilojoules (in MJ its terms read 0.0).
    if (const auto& f = s.forestEnergy; f.treeTerms() > 0) {
        const bool oneTree = scene.config().launch.enabled;
        const double u = oneTree ? 1e-3 : 1e-6;
        const char* unit = oneTree ? "kJ" : "MJ";
        std::printf("forest: the trees took %.1f %s (bending %.1f, axial damping %.2f, root %.1f, rupture %.1f), contacts %.1f %s; "
                    "left vibrating in stems put to sleep %.2f %s (%.1f %% of the trees' terms): %.2f %s the motion of broken "
                    "or uprooted stems' pieces, %.3f %s in standing stems and contact springs (%.1f %%)\n",
                    u * f.treeTerms(), unit, u * (f.bendingPlasticity + f.bendingDamping), u * f.axialDamping, u * f.rootPlasticity,
                    u * f.rupture, u * (f.contactFriction + f.contactDamping + f.contactCrushing), unit, u * f.frozen, unit,
                    100 * f.frozen / f.treeTerms(), u * f.frozenPieces, unit, u * (f.frozen - f.frozenPieces), unit,
                    100 * (f.frozen - f.frozenPieces) / f.treeTerms());
    }
    std::printf("results in %s/\n", out.c_str());
    // A block that left the terrain would have gone further: its run-out is a lower bound, and so is
    // Dist50 once half the blocks left.
    if (const auto left = s.stopReasons.find(dem::toString(dem::StopReason::LeftDomain)); left != s.stopReasons.end() && left->second > 0)
        std::cerr << "sylvarock simulate: warning: " << left->second << " of " << s.runs - s.failedRuns
                  << " runs left the terrain; their run-outs are where they left it, lower bounds"
                  << (2 * left->second >= s.runs - s.failedRuns ? ", and so is Dist50 (a longer slope would tell)" : "") << "\n";
    // So is a run cut by the time limit while the block still moved.
    if (const auto timed = s.stopReasons.find(dem::toString(dem::StopReason::TimeLimit)); timed != s.stopReasons.end() && timed->second > 0)
        std::cerr << "sylvarock simulate: warning: " << timed->second << " of " << s.runs - s.failedRuns
                  << " runs reached stop.max_time_s (" << readableNumber(scene.config().stop.maxTime)
                  << " s) still moving; their run-outs are where the time ran out, lower bounds"
                  << (2 * timed->second >= s.runs - s.failedRuns ? ", and so is Dist50" : "") << ": raise stop.max_time_s\n";
    if (s.failedRuns > 0) {
        std::cerr << "sylvarock simulate: " << s.failedRuns << " of " << s.runs
                  << " runs stopped on a numerical error and are left out of the statistics (stop_reason failed in "
                     "runs.csv):\n";
        int shown = 0;
        for (const auto& r : results)
            if (r.reason == dem::StopReason::Failed && shown++ < 3)
                std::cerr << "  run " << r.run << " (seed " << r.seed << "): " << r.failure << "\n";
        std::cerr << "  (to run one again alone, with the same options: --only-run N)\n";
        return kRunsFailed;
    }
    return 0;
}

const CommandRegistration reg{{3, "simulate", "run blocks down a slope (Monte Carlo, in parallel)", &runSimulate, true}};

}  // namespace
}  // namespace sylva::cli
