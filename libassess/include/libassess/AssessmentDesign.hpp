#pragma once
// What an assessment computes: which stands, on which scene, how many forest realisations (K), block
// runs per realisation (M) and baseline runs without forest (B), from which seed. Written to the
// output directory so that a resumed campaign can be refused if it asks for something else.
#include <cstdint>
#include <string>
#include <vector>

#include "libdem/Campaign.hpp"

namespace sylva::assess {

struct StandSource {
    std::string name;  // the basename of the prefix, e.g. "GR1"
    std::string stemsCsv, plotsCsv;
};

// "data/stands/GR1" -> GR1 with data/stands/GR1_stems.csv and data/stands/GR1_plots.csv. Throws
// InputError if either file is missing.
StandSource standFromPrefix(const std::string& prefix);

struct AssessmentDesign {
    std::vector<StandSource> stands;
    std::string sceneFile;
    std::vector<std::string> sceneOverrides;  // "section.key=value", over the scene file (--set)
    int runs = 100;            // M, block runs per forest realisation (the paper's 100)
    int realisations = 5;      // K, forests generated per stand and structure
    int baselineRuns = 1000;   // B, runs without forest
    std::uint64_t seed = 1;
    // The models that run the campaigns (the paper's Sect. 2.3: the DEM, and the lumped-mass model
    // as its RF3D). Each runs through the same virtual forests; the lumped model, ~10^4 times faster,
    // takes its own run counts.
    std::vector<dem::Model> models{dem::Model::Dem};
    int lumpedRuns = 2000;          // lumped runs per forest realisation
    int lumpedBaselineRuns = 3000;  // lumped runs without forest (the paper's Table 1 calibration count)
};

// Whether the design runs `model` at all (the other model's run counts then mean nothing).
bool usesModel(const AssessmentDesign& design, dem::Model model);
// Block runs per forest realisation, and without forest, of one model.
int runsPerRealisation(const AssessmentDesign& design, dem::Model model);
int baselineRuns(const AssessmentDesign& design, dem::Model model);

// "dem" | "lumped" | "both" (the --model option of assess); InputError otherwise.
std::vector<dem::Model> parseModels(const std::string& name);

// InputError for: no stand, two stands of one name, no model or one twice, a run count below 1 or
// above 10^7, more than 10^4 realisations.
void validate(const AssessmentDesign& design);

// The design as text, one `key = value` per line: the counts, the seed, the scene's overrides and
// stem parameter set, and each input file by name and a fingerprint of its contents (scene file,
// its slope profile or DTM, each stand's two files).
// Paths are written as comments: moving the data does not change the design, editing it does.
std::string designText(const AssessmentDesign& design);

// Throws InputError naming `where` (the campaign store), the line and both values at the first line
// where the stored design text differs from `design`'s (comments are ignored). Returns a note when
// the stored design was written by another build of sylvarock: not refused, as most builds change no
// run, but said, as a build that changed the physics makes other runs of the same seeds.
std::string requireSameDesign(const std::string& storedText, const std::string& where, const AssessmentDesign& design);

}  // namespace sylva::assess
