#include "libassess/ProtectionAnalysis.hpp"

#include <stdexcept>

#include "libassess/Correlation.hpp"
#include "libassess/Hashing.hpp"
#include "libassess/ProtectionIndex.hpp"
#include "libdem/CampaignSummary.hpp"

namespace sylva::assess {

namespace {

// The campaign's runs that have a run-out; those that stopped on a numerical error are named in
// `failed` instead (they are stored, so a resumed campaign does not run them again).
std::vector<RunRecord> completeRuns(const CampaignStore& store, std::size_t c, const Campaign& campaign,
                                    std::vector<std::string>& failed) {
    const auto& records = store.runs(c);
    if (static_cast<int>(records.size()) != campaign.runs)
        throw std::logic_error("campaign " + campaign.id + " is not complete: " + std::to_string(records.size()) + " of " +
                               std::to_string(campaign.runs) + " runs");
    std::vector<RunRecord> runs;
    for (const auto& [run, record] : records)
        if (record.reason == dem::toString(dem::StopReason::Failed))
            failed.push_back(campaign.id + " run " + std::to_string(run) + " (seed " + std::to_string(record.seed) + ")");
        else
            runs.push_back(record);
    if (runs.empty())
        throw CampaignWithoutFinishedRuns(
            "all " + std::to_string(records.size()) + " runs of campaign " + campaign.id +
            " stopped on a numerical error (each was reported as it failed): without a finished run it has no Dist50, "
            "so no PF50. Remove the cause (a forced integration.dt_s, an extreme --set) and start again with another --out");
    return runs;
}

std::vector<double> runouts(const std::vector<RunRecord>& runs) {
    std::vector<double> v;
    for (const auto& r : runs) v.push_back(r.runoutM);
    return v;
}

void rankWithinStructures(std::vector<StructureAssessment>& rows, std::vector<DendrometricCorrelation>& correlations) {
    for (auto structure : assessedStructures()) {
        std::vector<StructureAssessment*> group;
        std::vector<double> pf, g, d, n;
        for (auto& row : rows)
            if (row.structure == structure) {
                group.push_back(&row);
                pf.push_back(row.pf50);
                g.push_back(row.inventory.basalAreaM2Ha);
                d.push_back(row.inventory.meanDbhCm);
                n.push_back(row.inventory.stemsPerHa);
            }
        const auto byPf = ascendingRanks(pf), byG = ascendingRanks(g);
        for (std::size_t i = 0; i < group.size(); ++i) {
            group[i]->rankPf50 = byPf[i];
            group[i]->rankBasalArea = byG[i];
        }
        DendrometricCorrelation c{structure, group.size(), pearson(pf, g), pearson(pf, d), pearson(pf, n)};
        c.pBasalArea = pearsonPValue(c.basalArea, c.stands);
        c.pMeanDbh = pearsonPValue(c.meanDbh, c.stands);
        c.pStemsPerHa = pearsonPValue(c.stemsPerHa, c.stands);
        correlations.push_back(c);
    }
}

}  // namespace

AssessmentResults analyse(const AssessmentDesign& design, dem::Model model, const std::vector<Campaign>& plan,
                          const CampaignStore& store, const std::vector<ForestSummary>& inventories,
                          const BootstrapSettings& bootstrap) {
    AssessmentResults out;
    out.design = design;
    out.model = model;
    out.bootstrap = bootstrap;
    std::vector<double> baseline;
    for (std::size_t c = 0; c < plan.size(); ++c) {
        const Campaign& campaign = plan[c];
        if (campaign.model != model) continue;
        std::vector<RunRecord> runs = completeRuns(store, c, campaign, out.failedRuns);
        if (!campaign.forested) {
            out.baseline = std::move(runs);
            continue;
        }
        // Campaigns come stand by stand, structure by structure, realisation 1 first (planCampaigns).
        if (campaign.realisation == 1) {
            StructureAssessment row;
            row.name = design.stands.at(campaign.stand).name;
            row.structure = campaign.structure;
            row.inventory = inventories.at(campaign.stand);
            out.stands.push_back(std::move(row));
        }
        if (!store.forest(c)) throw std::logic_error("campaign " + campaign.id + " is complete but its forest's statistics are missing");
        out.stands.back().forests.push_back(*store.forest(c));
        out.stands.back().runs.push_back(std::move(runs));
    }
    baseline = runouts(out.baseline);
    out.baselineDist50 = dem::quantile(baseline, 0.5);
    for (auto& row : out.stands) {
        std::vector<std::vector<double>> perRealisation;
        std::vector<double> pooled;
        for (const auto& runs : row.runs) {
            perRealisation.push_back(runouts(runs));
            pooled.insert(pooled.end(), perRealisation.back().begin(), perRealisation.back().end());
            row.pf50PerRealisation.push_back(protectionIndex(perRealisation.back(), baseline));
        }
        row.dist50 = dem::quantile(pooled, 0.5);
        row.pf50 = protectionIndex(row.dist50, out.baselineDist50);  // Eq. 26
        BootstrapSettings b = bootstrap;
        b.seed = derivedSeed(design.seed, seedKeyPrefix(model) + "bootstrap|" + row.name + "|" + structureCode(row.structure));
        row.pf50Ci = bootstrapProtectionIndex(perRealisation, baseline, b);
    }
    rankWithinStructures(out.stands, out.correlations);
    return out;
}

}  // namespace sylva::assess
