#pragma once
// The block campaigns an assessment runs: the baseline without forest, and for every stand, structure
// (A, NA) and realisation k one generated forest with its own campaign of runs. Each has seeds derived
// from (seed, stand, structure, k) alone, so adding a stand or more realisations leaves the others'
// results unchanged, and none depends on the order or the threads they run on.
#include <cstdint>
#include <string>
#include <vector>

#include "libassess/AssessmentDesign.hpp"
#include "libstand/ForestGenerator.hpp"

namespace sylva::assess {

// The paper's labels: "A" (aggregated) and "NA" (not aggregated, i.e. random).
std::string structureCode(stand::ForestStructure structure);
const std::vector<stand::ForestStructure>& assessedStructures();  // A, then NA

struct Campaign {
    bool forested = false;          // false: the baseline
    std::size_t stand = 0;          // index in the design's stands (forested only)
    stand::ForestStructure structure = stand::ForestStructure::Aggregated;
    int realisation = 0;            // 1..K (forested only)
    std::uint32_t forestSeed = 0;   // GenerationSettings::seed
    std::uint32_t runSeed = 0;      // CampaignOptions::seed
    int runs = 0;
    std::string id;                 // "baseline" or e.g. "GR1_A_003": names its files and progress lines
};

// Baseline first, then stands in design order, A before NA, realisations 1..K.
std::vector<Campaign> planCampaigns(const AssessmentDesign& design);

}  // namespace sylva::assess
