// Error against run time (issue 6): what each knob that trades accuracy for speed costs. Every
// setting changes one knob from the scene defaults; each is compared with a reference setting where
// every knob is at its fine end, on
//  - forested runs (data/scenes/no-forest.ini through MO1 aggregated over x in [130, 630] m), paired
//    with the reference's (same seeds, so the same releases): |run-out - run-out_ref| per run, and
//    the distribution-level errors in Dist50 and in PF50 (Eq. 26, the no-forest Dist50 from the same
//    setting's no-forest runs);
//  - single-tree launches (data/scenes/single-tree.ini): the relative error in the energy the tree
//    takes from the block (its kinetic energy before minus after the impact).
// The dynamics in a forest are chaotic: paired run-out errors do not vanish however fine the setting,
// so the distribution-level errors are the ones to judge a setting by. The reference's forested runs
// cost ~4 times the defaults' (5.7 s against 1.5 s CPU each) and 0.25 m nodes ~13 times: 12 runs per
// setting took 6 minutes on 2 threads (docs/accuracy.md).
// Prints one CSV row per setting (to stdout or --out); bench/accuracy_plot.sh draws error against CPU
// time with the Pareto front. Run from anywhere: bench_accuracy --help.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <boost/program_options.hpp>

#include "libassess/CampaignRunner.hpp"
#include "libassess/ProtectionIndex.hpp"
#include "libdem/Campaign.hpp"
#include "libdem/CampaignSummary.hpp"
#include "libdem/SimulationError.hpp"
#include "libstand/ForestGenerator.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Inventory.hpp"

namespace po = boost::program_options;
using namespace sylva;

namespace {

const std::string kData = SYLVAROCK_DATA_DIR;

// A scene key and the values it is tried at (the other knobs at their defaults).
struct Knob {
    std::string key;
    std::vector<std::string> values;
};

// Each knob at a finer and a cheaper value than its default (SceneConfig.hpp); integration.stem_safety
// defaults to 0.95, as close to the stems' stable limit as it goes, so its second value is the default itself;
// stem.upper_spacing_factor defaults to its fine end (1, the uniform stem), so both its values are cheaper.
const std::vector<Knob> kKnobs = {
    {"integration.safety", {"0.15", "0.6"}},
    {"integration.stem_safety", {"0.4", "0.95"}},
    {"stem.node_spacing_m", {"0.25", "1.0"}},
    {"stem.upper_spacing_factor", {"2", "4"}},  // its default, 1, is its fine end
    {"forest.wake_margin_m", {"0.05", "0.3"}},
    {"forest.sleep_after_s", {"0.0125", "0.1"}},
    {"forest.return_horizon_s", {"0.05", "0.4"}},
};

// Every numerical knob at its fine end: the runs the others are compared with. The node spacing
// stays at its default: it is also the length of the plastic hinge Fig. 3 applies to (the rotation
// a connection takes from M_Elast to M_Rupt grows with it), so it is a model parameter as much as a
// resolution; its rows show that sensitivity against this reference (docs/accuracy.md).
const std::vector<std::string> kReference = {
    "integration.safety=0.075", "integration.stem_safety=0.4", "forest.wake_margin_m=0.3", "forest.sleep_after_s=1.0",
    "forest.return_horizon_s=0.4",
};

struct Setting {
    std::string name, knob, value;
    std::vector<std::string> overrides;
};

struct StudyInputs {
    stand::Forest forest;
    int runs = 4, baselineRuns = 100, threads = 2;
    unsigned long seed = 1;
    std::vector<std::string> treeDbhCm, treeSpeed;  // single-tree cases: every DBH at every speed
};

// What one setting gives.
struct Measurement {
    std::vector<double> runout;         // forested runs, m, in run order (paired across settings by seed)
    std::vector<double> runoutNoForest;
    std::vector<double> treeDissipated;  // J, one per single-tree case
    std::vector<double> cpuForest, cpuTree;  // s per run
};

// Calls body(i) for i in [0, n) on `threads` threads; rethrows the first exception.
template <class Body>
void parallelFor(int n, int threads, Body body) {
    std::atomic<int> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    std::vector<std::thread> pool;
    for (int t = 0; t < std::max(1, threads); ++t)
        pool.emplace_back([&] {
            for (int i = next++; i < n; i = next++) {
                try {
                    body(i);
                } catch (...) {
                    std::lock_guard<std::mutex> lock(failureMutex);
                    if (!failure) failure = std::current_exception();
                    next = n;
                }
            }
        });
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

std::vector<dem::RunResult> campaign(const dem::Scene& scene, int runs, const StudyInputs& in) {
    dem::CampaignOptions o;
    o.runs = runs;
    o.seed = in.seed;
    o.threads = in.threads;
    return dem::runCampaign(scene, o);
}

// The energy the tree takes from a block launched at it: what its stem dissipated in bending
// (plastic and viscous), at the root and at rupture, and by friction against the block. Not the
// block's kinetic energy before minus after the impact: while touching the stem the block also
// bounces on the soil, and when that contact ends decides the "after" (at 20 m/s on a 15 cm stem
// the block's energy after varies by 25 % between steps whose stem terms agree within 5 %).
double treeDissipation(const dem::RunResult& r, const std::string& what) {
    if (r.impacts.empty()) throw dem::SimulationError(what + ": the block never touched the tree");
    const dem::ForestLedger& f = r.forestEnergy;
    return f.bendingPlasticity + f.bendingDamping + f.rootPlasticity + f.rupture + f.contactFriction;
}

Measurement measure(const Setting& s, const StudyInputs& in) {
    Measurement m;
    const dem::SceneConfig bare = dem::loadScene(kData + "/scenes/no-forest.ini", s.overrides);
    for (const auto& r : campaign(dem::Scene(bare), in.baselineRuns, in)) m.runoutNoForest.push_back(r.runoutAlongSlope);
    for (const auto& r : campaign(dem::Scene(bare, in.forest), in.runs, in)) {
        m.runout.push_back(r.runoutAlongSlope);
        m.cpuForest.push_back(r.cpuSeconds);
    }
    const std::size_t cases = in.treeDbhCm.size() * in.treeSpeed.size();
    m.treeDissipated.resize(cases);
    m.cpuTree.resize(cases);
    parallelFor(static_cast<int>(cases), in.threads, [&](int i) {
        const std::string& dbh = in.treeDbhCm[i / in.treeSpeed.size()];
        const std::string& speed = in.treeSpeed[i % in.treeSpeed.size()];
        std::vector<std::string> overrides = s.overrides;
        overrides.push_back("tree.dbh_cm=" + dbh);
        overrides.push_back("block.speed_m_s=" + speed);
        const dem::Scene tree(dem::loadScene(kData + "/scenes/single-tree.ini", overrides));
        const dem::RunResult r = dem::simulateBlock(tree, 0, dem::runSeed(in.seed, 0));
        m.treeDissipated[i] = treeDissipation(r, "single tree of " + dbh + " cm at " + speed + " m/s");
        m.cpuTree[i] = r.cpuSeconds;
    });
    return m;
}

std::vector<double> absoluteDifferences(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> d;
    for (std::size_t i = 0; i < a.size(); ++i) d.push_back(std::abs(a[i] - b[i]));
    return d;
}

std::vector<double> relativeDifferences(const std::vector<double>& a, const std::vector<double>& reference) {
    std::vector<double> d;
    for (std::size_t i = 0; i < a.size(); ++i) d.push_back(std::abs(a[i] - reference[i]) / reference[i]);
    return d;
}

double pf50(const Measurement& m) { return assess::protectionIndex(m.runout, m.runoutNoForest); }

const char* kHeader =
    "setting,knob,value,runs,cpu_s_per_run_median,tree_cpu_s_median,runout_err_median_m,runout_err_p90_m,"
    "dist50_m,dist50_err_m,pf50,pf50_err,tree_energy_err_median,tree_energy_err_max,status\n";

std::string row(const Setting& s, const Measurement& m, const Measurement& ref) {
    using dem::quantile;
    const auto runoutErr = absoluteDifferences(m.runout, ref.runout);
    const auto energyErr = relativeDifferences(m.treeDissipated, ref.treeDissipated);
    const double dist50 = quantile(m.runout, 0.5);
    char line[512];
    std::snprintf(line, sizeof line, "%s,%s,%s,%zu,%.4g,%.4g,%.4g,%.4g,%.2f,%.4g,%.4f,%.4g,%.4g,%.4g,ok\n",
                  s.name.c_str(), s.knob.c_str(), s.value.c_str(), m.runout.size(), quantile(m.cpuForest, 0.5),
                  quantile(m.cpuTree, 0.5), quantile(runoutErr, 0.5), quantile(runoutErr, 0.9), dist50,
                  std::abs(dist50 - quantile(ref.runout, 0.5)), pf50(m), std::abs(pf50(m) - pf50(ref)),
                  quantile(energyErr, 0.5), quantile(energyErr, 1));
    return line;
}

std::vector<std::string> splitList(const std::string& option, const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    for (std::string v; std::getline(ss, v, ',');) {
        if (v.empty()) throw InputError("--" + option + ": empty value in '" + text + "'");
        out.push_back(v);
    }
    if (out.empty()) throw InputError("--" + option + ": give at least one value");
    return out;
}

// "key=v1,v2,..." -> a knob.
Knob parseKnob(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError("--vary: expected KEY=V1,V2,... (e.g. integration.safety=0.15,0.6), got '" + text + "'");
    return {text.substr(0, eq), splitList("vary", text.substr(eq + 1))};
}

std::vector<Setting> settingsOf(const std::vector<Knob>& knobs) {
    std::vector<Setting> settings{{"defaults", "", "", {}}};
    for (const auto& k : knobs)
        for (const auto& v : k.values) settings.push_back({k.key + "=" + v, k.key, v, {k.key + "=" + v}});
    return settings;
}

// MO1 aggregated, as `sylvarock generate --structure aggregated --extent 130,0,630,200 --seed S`:
// the extent is the assessments' (from 30 m below the release to the end of the slope).
stand::Forest mo1Forest(unsigned long seed) {
    const std::string stems = kData + "/stands/MO1_stems.csv";
    const stand::StandCatalogue catalogue(stand::readInventory(stems, kData + "/stands/MO1_plots.csv"), stems);
    stand::GenerationSettings g;
    g.structure = stand::ForestStructure::Aggregated;
    g.seed = seed;
    const dem::Scene bare(dem::loadScene(kData + "/scenes/no-forest.ini"));
    return stand::generateForest(catalogue, assess::forestExtent(bare), g).forest;
}

int study(int argc, char** argv) {
    po::options_description o("bench_accuracy: error against CPU time of the knobs that trade accuracy for speed");
    std::vector<std::string> vary;
    o.add_options()
        ("help", "this help")
        ("runs", po::value<int>()->default_value(4),
         "forested runs per setting (paired: the same seeds in every setting); the reference costs ~100x the defaults per run")
        ("baseline-runs", po::value<int>()->default_value(100), "no-forest runs per setting, for PF50's Dist50 without forest (Eq. 26)")
        ("threads", po::value<int>()->default_value(2), "worker threads")
        ("seed", po::value<unsigned long>()->default_value(1), "campaign seed of the block runs")
        ("forest", po::value<std::string>(), "forest CSV in the slope's frame (default: MO1 aggregated over 130,0,630,200 from --forest-seed)")
        ("forest-seed", po::value<unsigned long>()->default_value(3), "seed of the generated MO1 forest")
        ("vary", po::value(&vary)->composing(),
         "KEY=V1,V2,...: a knob and its values (repeatable; replaces the built-in list of five knobs)")
        ("tree-dbh", po::value<std::string>()->default_value("15,25,40"), "single-tree cases: DBHs, cm")
        ("tree-speed", po::value<std::string>()->default_value("10,20"), "single-tree cases: launch speeds, m/s")
        ("out", po::value<std::string>(), "CSV file (default: stdout)");
    po::variables_map vm;
    po::store(po::parse_command_line(argc, argv, o), vm);
    po::notify(vm);
    if (vm.count("help")) {
        std::cout << o << "\nReference: ";
        for (const auto& r : kReference) std::cout << r << ' ';
        std::cout << "\nPlot: bench/accuracy_plot.sh accuracy.csv accuracy.svg\n";
        return 0;
    }
    StudyInputs in;
    in.runs = vm["runs"].as<int>();
    in.baselineRuns = vm["baseline-runs"].as<int>();
    in.threads = vm["threads"].as<int>();
    in.seed = vm["seed"].as<unsigned long>();
    if (in.runs < 2 || in.baselineRuns < 1 || in.threads < 1)
        throw InputError("--runs must be at least 2, --baseline-runs and --threads at least 1");
    in.treeDbhCm = splitList("tree-dbh", vm["tree-dbh"].as<std::string>());
    in.treeSpeed = splitList("tree-speed", vm["tree-speed"].as<std::string>());
    in.forest = vm.count("forest") ? stand::readForestCsv(vm["forest"].as<std::string>())
                                   : mo1Forest(vm["forest-seed"].as<unsigned long>());
    if (in.forest.trees.empty()) throw InputError("--forest: the forest has no stems");
    std::vector<Knob> knobs;
    for (const auto& v : vary) knobs.push_back(parseKnob(v));
    const auto settings = settingsOf(knobs.empty() ? kKnobs : knobs);
    for (const auto& s : settings) dem::sceneFromOverrides(s.overrides);  // a bad key or value stops here, not mid-study

    std::ofstream file;
    if (vm.count("out")) {
        file.open(vm["out"].as<std::string>());
        if (!file) throw InputError(vm["out"].as<std::string>() + ": cannot write");
    }
    std::ostream& out = vm.count("out") ? file : std::cout;

    std::cerr << "forest of " << in.forest.trees.size() << " stems; " << settings.size() + 1 << " settings, " << in.runs
              << " forested runs each, " << in.threads << " threads\n";
    const Setting reference{"reference", "", "", kReference};
    const Measurement ref = measure(reference, in);
    for (double e : ref.treeDissipated)
        if (!(e > 0)) throw dem::SimulationError("reference: a single tree took no energy from the block, so relative errors are undefined");
    out << kHeader << row(reference, ref, ref) << std::flush;
    std::cerr << "reference: CPU per forested run " << dem::quantile(ref.cpuForest, 0.5) << " s\n";
    for (const auto& s : settings) {
        try {
            const Measurement m = measure(s, in);
            out << row(s, m, ref) << std::flush;
            std::cerr << s.name << ": CPU per forested run " << dem::quantile(m.cpuForest, 0.5) << " s\n";
        } catch (const dem::SimulationError& e) {
            // A setting that cannot run (unstable, energy not conserved) is a result, not the end of the study.
            out << s.name << ',' << s.knob << ',' << s.value << ",0,,,,,,,,,,,failed\n" << std::flush;
            std::cerr << s.name << ": failed: " << e.what() << "\n";
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return study(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "bench_accuracy: " << e.what() << "\n";
        return 1;
    }
}
