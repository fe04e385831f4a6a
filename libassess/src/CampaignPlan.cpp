#include "libassess/CampaignPlan.hpp"

#include <cstdio>

#include "libassess/Hashing.hpp"

namespace sylva::assess {

std::string structureCode(stand::ForestStructure structure) {
    return structure == stand::ForestStructure::Aggregated ? "A" : "NA";
}

const std::vector<stand::ForestStructure>& assessedStructures() {
    static const std::vector<stand::ForestStructure> all{stand::ForestStructure::Aggregated, stand::ForestStructure::Random};
    return all;
}

std::string seedKeyPrefix(dem::Model model) { return model == dem::Model::Dem ? "" : dem::toString(model) + "|"; }

std::vector<Campaign> planCampaigns(const AssessmentDesign& design) {
    std::vector<Campaign> plan;
    for (auto model : design.models) {
        const std::string prefix = seedKeyPrefix(model);
        const std::string idPrefix = model == dem::Model::Dem ? "" : dem::toString(model) + "_";
        Campaign baseline;
        baseline.model = model;
        baseline.runSeed = derivedSeed(design.seed, prefix + "runs|baseline");
        baseline.runs = baselineRuns(design, model);
        baseline.id = idPrefix + "baseline";
        plan.push_back(baseline);
        for (std::size_t s = 0; s < design.stands.size(); ++s)
            for (auto structure : assessedStructures())
                for (int k = 1; k <= design.realisations; ++k) {
                    Campaign c;
                    c.model = model;
                    c.forested = true;
                    c.stand = s;
                    c.structure = structure;
                    c.realisation = k;
                    const std::string key = design.stands[s].name + "|" + structureCode(structure) + "|" + std::to_string(k);
                    c.forestSeed = derivedSeed(design.seed, "forest|" + key);
                    c.runSeed = derivedSeed(design.seed, prefix + "runs|" + key);
                    c.runs = runsPerRealisation(design, model);
                    char number[16];
                    std::snprintf(number, sizeof number, "%03d", k);
                    c.id = idPrefix + design.stands[s].name + "_" + structureCode(structure) + "_" + number;
                    plan.push_back(c);
                }
    }
    return plan;
}

}  // namespace sylva::assess
