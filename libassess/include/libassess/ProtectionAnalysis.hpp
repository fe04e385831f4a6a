#pragma once
// What an assessment concludes from its stored runs: for every stand and structure the pooled Dist50
// and PF50 (Eq. 26) with a bootstrap interval, PF50 of each realisation alone, the stands' ranks by
// PF50 and by basal area (Fig. 11), and the correlation of PF50 with G, Mean_D and N (Fig. 12).
// Everything is computed from the stored runs, in run order, so a resumed campaign gives exactly the
// numbers of an uninterrupted one.
#include <stdexcept>
#include <string>
#include <vector>

#include "libassess/AssessmentDesign.hpp"
#include "libassess/Bootstrap.hpp"
#include "libassess/CampaignPlan.hpp"
#include "libassess/CampaignStore.hpp"
#include "libassess/ForestSummary.hpp"

namespace sylva::assess {

// Every run of a campaign stopped on a numerical error: it has no Dist50, so its stand no PF50.
struct CampaignWithoutFinishedRuns : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct StructureAssessment {
    std::string name;  // the stand's
    stand::ForestStructure structure = stand::ForestStructure::Aggregated;
    ForestSummary inventory;
    std::vector<ForestSummary> forests;        // per realisation
    std::vector<std::vector<RunRecord>> runs;  // per realisation, in run order
    double dist50 = 0;                         // median run-out of the pooled runs, m
    double pf50 = 0;                           // Eq. 26 against the baseline
    Interval pf50Ci;
    std::vector<double> pf50PerRealisation;
    int rankPf50 = 0, rankBasalArea = 0;       // among the stands of this structure, 1 = lowest
};

// Pearson's r of PF50 with the inventory's G, Mean_D and N over the stands of one structure (NaN
// below two stands), and each r's two-sided p-value (NaN below three).
struct DendrometricCorrelation {
    stand::ForestStructure structure = stand::ForestStructure::Aggregated;
    std::size_t stands = 0;
    double basalArea = 0, meanDbh = 0, stemsPerHa = 0;
    double pBasalArea = 0, pMeanDbh = 0, pStemsPerHa = 0;
};

// One model's results (the assessment holds one per model of its design).
struct AssessmentResults {
    AssessmentDesign design;
    dem::Model model = dem::Model::Dem;
    BootstrapSettings bootstrap;         // replicates and confidence; each row has its own derived seed
    std::vector<RunRecord> baseline;     // in run order
    double baselineDist50 = 0;
    std::vector<StructureAssessment> stands;  // design order, A then NA
    std::vector<std::string> failedRuns;  // runs that stopped on a numerical error, left out of everything above
    std::vector<DendrometricCorrelation> correlations;  // A, NA
    // Where the blocks can be (the map's frame) and where the forests start, m.
    double terrainXmin = 0, terrainXmax = 0, terrainYmin = 0, terrainYmax = 0, forestStartX = 0;
};

// The results of `model` from its campaigns in `plan`. `inventories`: one summary per stand of the
// design. Every campaign of the model must be complete in `store`, and every forest's statistics
// stored (std::logic_error otherwise: runMissing does both).
AssessmentResults analyse(const AssessmentDesign& design, dem::Model model, const std::vector<Campaign>& plan,
                          const CampaignStore& store, const std::vector<ForestSummary>& inventories,
                          const BootstrapSettings& bootstrap);

}  // namespace sylva::assess
