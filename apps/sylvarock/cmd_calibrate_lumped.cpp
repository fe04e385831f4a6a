// sylvarock calibrate-lumped: fit the lumped model's roughness on the DEM's run-out without forest,
// as the paper calibrated Rockyfor3D (Sect. 2.3.2, Table 1), and store it in the scene's [lumped].
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "Cli.hpp"
#include "ProgressBar.hpp"
#include "libdem/Campaign.hpp"
#include "libdem/LumpedCalibration.hpp"
#include "libcommon/CsvTable.hpp"
#include "libcommon/InputError.hpp"
#include "libcommon/LineEnds.hpp"

namespace sylva::cli {
namespace {

// The run-outs of a `simulate` runs.csv on `scene`, failed runs left out. Rows another file could have
// (a run twice, from two campaigns' files joined; a stop reason simulate never writes; a run-out no
// path on the scene's bed reaches) are refused with their line: each would move the fit silently.
std::vector<double> readRunouts(const std::string& path, const dem::Scene& scene) {
    // The lumped model's own runs.csv has the same columns: fitted on it, the roughness fitted itself.
    const std::filesystem::path summary = std::filesystem::path(path).parent_path() / "summary.json";
    if (std::ifstream in{summary}) {
        const auto j = nlohmann::json::parse(in, nullptr, false);
        const std::string dem = dem::toString(dem::Model::Dem);
        if (!j.is_discarded() && j.is_object() && j.contains("model") && j["model"] != dem)
            throw InputError(path, 0, "these are runs of the " + (j["model"].is_string() ? j["model"].get<std::string>() : j["model"].dump()) +
                                          " model (" + summary.string() + "): calibrate on a DEM campaign's runs.csv (simulate --model dem)");
    }
    const auto t = CsvTable::read(path);
    const std::size_t runout = t.require("runout_m"), reason = t.require("stop_reason"), run = t.require("run");
    // The lumped soil is calibrated on bare ground: run-outs shortened by trees would make it rougher.
    const auto impacts = t.index("tree_impacts");
    const dem::SoilBed& bed = scene.soil();
    // Along the surface, no path is longer than the bed's diagonal over the cosine of a 70 degree slope.
    const double longest = 3 * std::hypot(bed.xmax() - bed.xmin(), bed.ymax() - bed.ymin());
    std::set<std::string> reasons;
    std::string listed;
    for (const auto r : dem::kStopReasons) {
        reasons.insert(dem::toString(r));
        listed += (listed.empty() ? "" : ", ") + dem::toString(r);
    }
    // Each run's release must be one this scene draws: a campaign released elsewhere (another x, a
    // y outside the range, another fall height or bed) fitted the lumped soil to another slope.
    const auto rx = t.index("release_x"), ry = t.index("release_y"), rz = t.index("release_z");
    const dem::ReleaseConfig& rel = scene.config().release;
    constexpr double kWritten = 1e-3;  // m: runs.csv gives 4 decimals
    const auto releasedHere = [&](double x, double y, double z) {
        if (std::abs(x - rel.x) > kWritten || y < rel.yMin - kWritten || y > rel.yMax + kWritten) return false;
        if (x < bed.xmin() || x > bed.xmax() || y < bed.ymin() || y > bed.ymax()) return false;
        return std::abs(z - bed.surfaceHeight(x, y) - rel.fallHeight) <= kWritten;
    };
    std::map<long, long> seen;  // run -> line
    std::vector<double> out;
    for (std::size_t i = 0; i < t.rows(); ++i) {
        const long id = t.integer(i, run);
        if (rx && ry && rz && !releasedHere(t.number(i, *rx), t.number(i, *ry), t.number(i, *rz))) {
            std::ostringstream os;
            os << "released at (" << t.text(i, *rx) << ", " << t.text(i, *ry) << ", " << t.text(i, *rz) << "), where this scene releases at x = "
               << readableNumber(rel.x) << " m, y " << (rel.yMax > rel.yMin ? "in [" + readableNumber(rel.yMin) + ", " + readableNumber(rel.yMax) + "]" : "= " + readableNumber(rel.yMin))
               << " m, " << readableNumber(rel.fallHeight) << " m above its bed: a runs.csv of another scene? calibrate on a campaign of this scene";
            t.fail(i, *rx, os.str());
        }
        if (const auto [at, fresh] = seen.emplace(id, t.lineOf(i)); !fresh)
            t.fail(i, run, "run " + std::to_string(id) + " is also on line " + std::to_string(at->second) +
                               ": two campaigns' runs.csv joined? calibrate on one campaign's file");
        if (impacts && !t.text(i, *impacts).empty() && t.number(i, *impacts) > 0)
            t.fail(i, *impacts, "this run hit trees: calibrate on a campaign without forest (simulate with no --forest)");
        if (!reasons.count(t.text(i, reason)))
            t.fail(i, reason, "stop reason '" + t.text(i, reason) + "' is not one simulate writes (" + listed + ")");
        if (t.text(i, reason) == dem::toString(dem::StopReason::Failed)) continue;
        const double x = t.number(i, runout);
        if (!(x >= 0 && x <= longest))
            t.fail(i, runout, "run-out " + t.text(i, runout) + " m: outside 0 to " + std::to_string(static_cast<long>(longest)) +
                                  " m, the longest path on this scene's bed; a runs.csv of another scene?");
        out.push_back(x);
    }
    if (out.size() < 100)
        throw InputError(path, 0, std::to_string(out.size()) + " finished runs: a Dist50 to calibrate on needs at least 100 (the paper used 3 000)");
    return out;
}

// The scene file with `keys` set in its [lumped] section (appended if it had none), under `comment`.
// The section's other keys and comments stay: the fit was made with them, and the scene must
// reproduce it. A former fit's comment lines (`kFitComments`) go with the keys they described.
const char* const kFitComments[] = {"# calibrated with:", "# DEM Dist50"};

void rewriteLumpedSection(const std::string& path, const std::string& comment,
                          const std::vector<std::pair<std::string, std::string>>& keys) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path, 0, "cannot open scene file");
    const std::string original((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    // The file keeps its line ends (CR LF from Windows, CR alone from old Mac editors): mixed ones
    // confuse editors and diffs.
    const std::size_t firstFeed = original.find('\n');
    const std::string lineEnd = firstFeed == std::string::npos ? (original.find('\r') == std::string::npos ? "\n" : "\r")
                                : firstFeed > 0 && original[firstFeed - 1] == '\r' ? "\r\n"
                                                                                   : "\n";
    std::istringstream in(withCrOnlyLineEndsAsLineFeeds(original));
    const auto trimmed = [](const std::string& s) {
        const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
        return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
    };
    std::ostringstream kept;
    std::vector<std::string> others;  // the section's lines that stay
    std::string line;
    bool inLumped = false, beforeSections = true;
    const auto fitted = [&](const std::string& key) { return std::any_of(keys.begin(), keys.end(), [&](const auto& k) { return k.first == key; }); };
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string t = trimmed(line);
        const auto eq = t.find('=');
        const std::string key = eq == std::string::npos ? std::string() : trimmed(t.substr(0, eq));
        if (!t.empty() && t[0] == '[') {
            beforeSections = false;
            inLumped = t.rfind("[lumped]", 0) == 0;
            if (inLumped) continue;
        }
        if (!inLumped) {
            // A fitted key given with its section's name before any section (lumped.rg70_m = ...) would be
            // given twice once the section below sets it: the scene would no longer load.
            if (!(beforeSections && key.rfind("lumped.", 0) == 0 && fitted(key.substr(7)))) kept << line << '\n';
            continue;
        }
        const bool fitComment = std::any_of(std::begin(kFitComments), std::end(kFitComments),
                                            [&](const char* c) { return t.rfind(c, 0) == 0; });
        if (!fitComment && !fitted(key)) others.push_back(line);
    }
    std::string text = kept.str();
    while (text.size() > 1 && text[text.size() - 1] == '\n' && text[text.size() - 2] == '\n') text.pop_back();
    while (!others.empty() && trimmed(others.back()).empty()) others.pop_back();
    std::ostringstream section;
    section << text << '\n' << "[lumped]\n" << comment;
    for (const std::string& l : others) section << l << '\n';
    for (const auto& [key, value] : keys) section << key << " = " << value << '\n';
    std::ofstream out(path + ".tmp", std::ios::binary);
    for (const char c : section.str()) {
        if (c == '\n') out << lineEnd;
        else out << c;
    }
    out.close();
    if (!out || std::rename((path + ".tmp").c_str(), path.c_str()) != 0)
        throw InputError(path, 0, "could not rewrite the scene file");
}

int runCalibrateLumped(int argc, const char* const* argv) {
    po::options_description o("calibrate-lumped");
    o.add_options()
        ("scene", po::value<std::string>(), "scene INI file without forest; its [lumped] keys other than the roughness are kept")
        ("dem-runs", po::value<int>()->default_value(1000), "DEM runs without forest to calibrate on (ignored with --dem)")
        ("dem", po::value<std::string>(), "or the runs.csv of a DEM campaign without forest on this scene (sylvarock simulate)")
        ("runs", po::value<int>()->default_value(3000), "lumped runs per trial roughness (the paper: 3 000)")
        ("seed", po::value<Seed>()->default_value(Seed{}, "1"), "seed of the DEM runs, the lumped runs and the bootstraps")
        ("threads", po::value<int>()->default_value(0), "worker threads (0: all cores); results do not depend on it")
        ("write", po::bool_switch(), "store the fit in the scene file's [lumped] section (its roughness and soil type; the other keys stay)");
    po::variables_map vm;
    if (!parse(argc, argv, o, vm, "sylvarock calibrate-lumped --scene FILE.ini [--dem runs.csv | --dem-runs N] [--write]",
               "  sylvarock calibrate-lumped --scene data/scenes/no-forest.ini --dem-runs 1000 --write\n"
               "  sylvarock calibrate-lumped --scene data/scenes/no-forest.ini --dem out/no-forest/runs.csv\n"))
        return 0;
    if (!vm.count("scene")) throw InputError("--scene is required (e.g. data/scenes/no-forest.ini)");
    const std::string scenePath = vm["scene"].as<std::string>();
    const dem::Scene scene(dem::loadScene(scenePath));
    if (scene.forested()) throw InputError(scenePath, 0, "calibrate on a scene without forest (the paper's Sect. 2.3.2)");
    const int lumpedRuns = vm["runs"].as<int>(), demRuns = vm["dem-runs"].as<int>();
    if (lumpedRuns < 100) throw InputError("--runs " + std::to_string(lumpedRuns) + ": a Dist50 needs at least 100 runs");
    const unsigned long seed = vm["seed"].as<Seed>().value;
    const int threads = threadCount(vm);

    std::vector<double> dem;
    if (vm.count("dem")) {
        dem = readRunouts(vm["dem"].as<std::string>(), scene);
    } else {
        if (demRuns < 100) throw InputError("--dem-runs " + std::to_string(demRuns) + ": a Dist50 needs at least 100 runs");
        std::cerr << "DEM: " << demRuns << " runs without forest\n";
        dem::CampaignOptions c;
        c.runs = demRuns;
        c.seed = seed;
        c.threads = threads;
        ProgressBar bar(stderrIsTerminal());
        c.onRunDone = [&bar](const dem::RunResult&, int done, int total) { bar.update(done, total); };
        for (const auto& r : dem::runCampaign(scene, c))
            if (r.reason != dem::StopReason::Failed) dem.push_back(r.runoutAlongSlope);
    }
    dem::LumpedCalibrationOptions opt;
    opt.runs = lumpedRuns;
    opt.seed = seed;
    opt.threads = threads;
    const auto fit = dem::calibrateLumped(scene, dem, opt);
    std::printf("DEM without forest (%zu runs): Dist50 %.1f m [%.1f, %.1f], spread p90-p10 %.1f m [%.1f, %.1f]\n",
                dem.size(), fit.demDist50.value, fit.demDist50.low, fit.demDist50.high, fit.demSpread.value,
                fit.demSpread.low, fit.demSpread.high);
    std::printf("lumped, roughness %.4f m (%d runs): Dist50 %.1f m [%.1f, %.1f], spread %.1f m [%.1f, %.1f]\n",
                fit.roughness, lumpedRuns, fit.lumpedDist50.value, fit.lumpedDist50.low, fit.lumpedDist50.high,
                fit.lumpedSpread.value, fit.lumpedSpread.low, fit.lumpedSpread.high);
    std::printf("residual Dist50 %+.1f m; roughness %.4f m [%.4f, %.4f] over the DEM's Dist50 interval +- the fit's %.1f m; %d trials\n",
                fit.lumpedDist50.value - fit.demDist50.value, fit.roughness, fit.roughnessLow, fit.roughnessHigh,
                opt.tolerance, fit.trials);
    const auto& lp = scene.config().lumped;
    std::ostringstream comment, roughness;
    comment << kFitComments[0] << " sylvarock calibrate-lumped --scene " << scenePath
            << (vm.count("dem") ? " --dem " + vm["dem"].as<std::string>() : " --dem-runs " + std::to_string(demRuns))
            << " --runs " << lumpedRuns << " --seed " << seed << " --write\n"
            << kFitComments[1] << " " << fit.demDist50.value << " m [" << fit.demDist50.low << ", " << fit.demDist50.high
            << "], lumped " << fit.lumpedDist50.value << " m; spread (p90-p10) DEM " << fit.demSpread.value
            << " m, lumped " << fit.lumpedSpread.value << " m\n";
    roughness << fit.roughness;
    const std::vector<std::pair<std::string, std::string>> keys{
        {"soil_type", std::to_string(lp.soilType)}, {"rg70_m", roughness.str()}, {"rg20_m", roughness.str()}, {"rg10_m", roughness.str()}};
    if (vm["write"].as<bool>()) {
        rewriteLumpedSection(scenePath, comment.str(), keys);
        std::printf("written to %s [lumped] (its other keys kept)\n", scenePath.c_str());
    } else {
        std::printf("\n[lumped]\n%s", comment.str().c_str());
        for (const auto& [key, value] : keys) std::printf("%s = %s\n", key.c_str(), value.c_str());
        std::printf("(add --write to store it in %s, its other [lumped] keys kept)\n", scenePath.c_str());
    }
    return 0;
}

const CommandRegistration reg{{6, "calibrate-lumped", "fit the lumped model's soil on the DEM without forest (as the paper's Table 1)", &runCalibrateLumped}};

}  // namespace
}  // namespace sylva::cli
