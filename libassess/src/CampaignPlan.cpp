#include "libassess/CampaignPlan.hpp"

#include <cstdio>
#include <map>

#include "libassess/Hashing.hpp"
#include "libcommon/InputError.hpp"

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
    // Ids are names joined by "_": a stand named like another's lumped campaigns ("lumped_GR1" beside
    // GR1 with --model both) would share its campaigns' ids, and the store its rows.
    std::map<std::string, const Campaign*> byId;
    for (const Campaign& c : plan) {
        const auto [at, added] = byId.emplace(c.id, &c);
        if (added) continue;
        const auto name = [&](const Campaign& k) {
            return k.forested ? "stand '" + design.stands[k.stand].name + "' (" + dem::toString(k.model) + ")"
                              : "the " + dem::toString(k.model) + " campaign without forest";
        };
        throw InputError(name(*at->second) + " and " + name(c) + " give the same campaign id '" + c.id + "': rename the stand");
    }
    return plan;
}

}  // namespace sylva::assess
