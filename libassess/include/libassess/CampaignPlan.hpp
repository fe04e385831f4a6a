#pragma once
// The block campaigns an assessment runs, for each of its models: the baseline without forest, and for
// every stand, structure (A, NA) and realisation k one generated forest with its own campaign of runs.
// Each has seeds derived from (seed, model, stand, structure, k) alone, so adding a stand, a model or
// more realisations leaves the others' results unchanged, and none depends on the order or the
// threads they run on. The forest of (stand, structure, k) is the same for every model: the models
// are compared through the same trees, as the paper does.
#include <cstdint>
#include <string>
#include <vector>

#include "libassess/AssessmentDesign.hpp"
#include "libstand/ForestGenerator.hpp"

namespace sylva::assess {

// The paper's labels: "A" (aggregated) and "NA" (not aggregated, i.e. random).
std::string structureCode(stand::ForestStructure structure);
const std::vector<stand::ForestStructure>& assessedStructures();  // A, then NA

// What a model puts before the keys its seeds derive from: nothing for the DEM (its seeds are those
// of the campaigns before there was a choice of model), "lumped|" for the lumped model.
std::string seedKeyPrefix(dem::Model model);

struct Campaign {
    dem::Model model = dem::Model::Dem;
    bool forested = false;          // false: the baseline
    std::size_t stand = 0;          // index in the design's stands (forested only)
    stand::ForestStructure structure = stand::ForestStructure::Aggregated;
    int realisation = 0;            // 1..K (forested only)
    std::uint32_t forestSeed = 0;   // GenerationSettings::seed
    std::uint32_t runSeed = 0;      // CampaignOptions::seed
    int runs = 0;
    std::string id;                 // "baseline", "GR1_A_003"; the lumped model's "lumped_baseline", "lumped_GR1_A_003"
};

// Model by model (the design's order): baseline first, then stands in design order, A before NA,
// realisations 1..K.
std::vector<Campaign> planCampaigns(const AssessmentDesign& design);

}  // namespace sylva::assess
