#pragma once
// The paper's comparison of its two models (Sect. 3.2-3.3, Figs. 9-12): for every stand and
// structure the PF50 each model gives through the same virtual forests, whether the models order the
// stands alike, and whether each finds the random (NA) forests more protective than the aggregated
// (A) ones.
#include <string>
#include <vector>

#include "libassess/ProtectionAnalysis.hpp"

namespace sylva::assess {

struct StandModelComparison {
    std::string name;
    stand::ForestStructure structure = stand::ForestStructure::Aggregated;
    const StructureAssessment* first = nullptr;   // the row of each model's results
    const StructureAssessment* second = nullptr;
    // Whether the two intervals share a value: where they do not, this campaign tells the models apart.
    bool intervalsOverlap = false;
};

struct StructureModelAgreement {
    stand::ForestStructure structure = stand::ForestStructure::Aggregated;
    std::size_t stands = 0;
    // Pearson's r of the two models' ranks by PF50 (Spearman's rank correlation; tied stands share
    // their lowest rank) and its two-sided p-value, exact (all pairings of the ranks) up to 9 stands,
    // Student's t beyond; NaN below two (three) stands.
    double rankCorrelation = 0, rankCorrelationP = 0;
};

struct ModelComparison {
    const AssessmentResults* first = nullptr;
    const AssessmentResults* second = nullptr;
    std::vector<StandModelComparison> stands;       // the first model's order
    std::vector<StructureModelAgreement> agreement;  // A, NA
    // Per model (first, second): stands where NA's PF50 is above A's, out of the stands assessed.
    int naAboveA[2] = {0, 0};
    int standsWithBoth = 0;
};

// Throws std::invalid_argument if the two results are not of one design's stands and structures.
ModelComparison compareModels(const AssessmentResults& first, const AssessmentResults& second);

}  // namespace sylva::assess
