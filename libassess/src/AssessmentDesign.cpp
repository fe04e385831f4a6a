#include "libassess/AssessmentDesign.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "libassess/Hashing.hpp"
#include "libdem/SceneConfig.hpp"
#include "libcommon/BuildId.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::assess {

namespace {

std::string fileLine(const std::string& key, const std::string& path) {
    return key + " = " + toHex(fileFingerprint(path), 16) + "\n# " + key + " file: " +
           std::filesystem::absolute(path).lexically_normal().string() + "\n";
}

// The design's keys whose value is a file's fingerprint (fileLine).
const std::set<std::string> fileKeys{"scene", "scene_profile", "scene_dtm", "stand_stems", "stand_plots"};

std::vector<std::pair<long, std::string>> significantLines(std::istream& in) {
    std::vector<std::pair<long, std::string>> lines;
    std::string line;
    for (long n = 1; std::getline(in, line); ++n)
        if (!line.empty() && line[0] != '#') lines.emplace_back(n, line);
    return lines;
}

}  // namespace

StandSource standFromPrefix(const std::string& prefix) {
    StandSource s;
    s.name = std::filesystem::path(prefix).filename().string();
    s.stemsCsv = prefix + "_stems.csv";
    s.plotsCsv = prefix + "_plots.csv";
    if (s.name.empty()) throw InputError("--stand '" + prefix + "': expected a prefix such as data/stands/GR1");
    for (const auto& f : {s.stemsCsv, s.plotsCsv})
        if (!std::filesystem::is_regular_file(f))
            throw InputError("--stand '" + prefix + "': " + f + " does not exist (a stand is given by the prefix of " +
                             "its PREFIX_stems.csv and PREFIX_plots.csv)");
    return s;
}

bool usesModel(const AssessmentDesign& design, dem::Model model) {
    return std::find(design.models.begin(), design.models.end(), model) != design.models.end();
}

int runsPerRealisation(const AssessmentDesign& design, dem::Model model) {
    return model == dem::Model::Dem ? design.runs : design.lumpedRuns;
}

int baselineRuns(const AssessmentDesign& design, dem::Model model) {
    return model == dem::Model::Dem ? design.baselineRuns : design.lumpedBaselineRuns;
}

std::vector<dem::Model> parseModels(const std::string& name) {
    if (name == "both") return {dem::Model::Dem, dem::Model::Lumped};
    if (name == "dem" || name == "lumped") return {dem::parseModel(name)};
    throw InputError("--model '" + name + "': expected dem (the discrete element model), lumped (the lumped-mass model, "
                     "docs/lumped.md) or both (the two side by side, as the paper's Sect. 3)");
}

void validate(const AssessmentDesign& d) {
    if (d.stands.empty()) throw InputError("no stand to assess: give at least one --stand PREFIX");
    std::set<std::string> names;
    for (const auto& s : d.stands)
        if (!names.insert(s.name).second) throw InputError("stand '" + s.name + "' is given twice");
    if (d.models.empty()) throw InputError("no model to run: --model dem, lumped or both");
    if (d.models.size() == 2 && d.models[0] == d.models[1]) throw InputError("model '" + dem::toString(d.models[0]) + "' is given twice");
    // Every campaign's run list is allocated from these counts: a typo (an extra zero or six) is
    // refused before it is.
    const auto requireCount = [](const char* option, int value, int most) {
        if (value < 1) throw InputError(std::string(option) + " must be at least 1, got " + std::to_string(value));
        if (value > most)
            throw InputError(std::string(option) + " " + std::to_string(value) + " is above " + std::to_string(most) + ": a typo?");
    };
    constexpr int kMostRuns = 10000000, kMostRealisations = 10000;
    requireCount("--runs", d.runs, kMostRuns);
    requireCount("--realisations", d.realisations, kMostRealisations);
    requireCount("--baseline-runs", d.baselineRuns, kMostRuns);
    requireCount("--lumped-runs", d.lumpedRuns, kMostRuns);
    requireCount("--lumped-baseline-runs", d.lumpedBaselineRuns, kMostRuns);
}

std::string designText(const AssessmentDesign& d) {
    std::ostringstream out;
    out << "# sylvarock assess: the design of the campaign in this directory (checked by --resume)\n"
        << "format = 2\nseed = " << d.seed << "\n";
    // Each model's run counts only where it runs: a lumped-only campaign's --runs is not used, and
    // a resume must not be refused over it.
    const bool demRuns = usesModel(d, dem::Model::Dem);
    if (demRuns) out << "runs_per_realisation = " << d.runs << "\n";
    out << "realisations = " << d.realisations << "\n";
    if (demRuns) out << "baseline_runs = " << d.baselineRuns << "\n";
    for (auto model : d.models) {
        out << "model = " << dem::toString(model) << "\n";
        if (model == dem::Model::Lumped)
            out << "lumped_runs_per_realisation = " << d.lumpedRuns << "\nlumped_baseline_runs = " << d.lumpedBaselineRuns << "\n";
    }
    const dem::SceneConfig scene = dem::loadScene(d.sceneFile, d.sceneOverrides);
    out << fileLine("scene", d.sceneFile);
    for (const auto& o : d.sceneOverrides) out << "scene_set = " << o << "\n";
    out << "stem_parameters = " << scene.stemParameters << "\n";
    if (!scene.terrain.profile.empty()) out << fileLine("scene_profile", scene.terrain.profile);
    if (!scene.terrain.dtm.empty()) out << fileLine("scene_dtm", scene.terrain.dtm);
    out << "stands = " << d.stands.size() << "\n";
    for (const auto& s : d.stands) {
        out << "stand = " << s.name << "\n";
        out << fileLine("stand_stems", s.stemsCsv) << fileLine("stand_plots", s.plotsCsv);
    }
    out << sylva::madeByLine() << "\n";  // last: the lines above keep their numbers
    return out.str();
}

std::string requireSameDesign(const std::string& storedText, const std::string& where, const AssessmentDesign& design) {
    std::istringstream stored(storedText), wanted(designText(design));
    auto have = significantLines(stored);
    const auto want = significantLines(wanted);
    // Lumped-only designs written before 28 Nov. 2026 held the DEM's unused run counts: not part of
    // what their runs depend on, so not compared.
    const auto line = [&](const std::string& text) {
        return std::any_of(have.begin(), have.end(), [&](const auto& l) { return l.second == text; });
    };
    if (!line("model = dem"))
        have.erase(std::remove_if(have.begin(), have.end(),
                                  [](const auto& l) {
                                      return l.second.rfind("runs_per_realisation = ", 0) == 0 || l.second.rfind("baseline_runs = ", 0) == 0;
                                  }),
                   have.end());
    const std::string advice = "; resume with the options of that campaign, or start a new one with another --out";
    const auto keyOf = [](const std::string& l) { return l.substr(0, l.find(" = ")); };
    for (std::size_t i = 0; i < std::max(have.size(), want.size()); ++i) {
        if (i < have.size() && i < want.size() && have[i].second == want[i].second) continue;
        const long number = i < have.size() ? have[i].first : (have.empty() ? 0 : have.back().first);
        std::string what;
        if (i < have.size() && i < want.size() && keyOf(have[i].second) == keyOf(want[i].second)) {
            what = "the campaign there was started with '" + have[i].second + "', this one asks for '" + want[i].second + "'";
            // A file's line holds its fingerprint: hexadecimal digits, which say only that it changed.
            if (fileKeys.count(keyOf(want[i].second))) what += " (the file's contents are not those the campaign began with)";
        } else if (i < want.size() && !line(want[i].second)) {
            // A line one design has and the other lacks shifts the rest: named alone, not against its neighbour.
            what = "this one adds '" + want[i].second + "', which the campaign there was not started with";
        } else if (i < have.size()) {
            what = "the campaign there was started with '" + have[i].second + "', which this one lacks";
        } else {
            what = "this one adds '" + want[i].second + "'";
        }
        throw InputError(where + ", design line " + std::to_string(number) + ": " + what + advice);
    }
    std::istringstream lines(storedText);
    std::vector<std::string> storedLines;
    for (std::string text; std::getline(lines, text);) storedLines.push_back(text);
    return sylva::otherBuildNote(where, storedLines, "campaign");
}

}  // namespace sylva::assess
