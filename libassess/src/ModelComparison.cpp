#include "libassess/ModelComparison.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "libassess/CampaignPlan.hpp"
#include "libassess/Correlation.hpp"

namespace sylva::assess {

namespace {

std::vector<double> ranks(const std::vector<double>& values) {
    const auto r = ascendingRanks(values);
    return {r.begin(), r.end()};
}

// Up to this many stands the p-value is exact: the share of the n! pairings of the ranks whose
// correlation is at least as strong (9! = 362 880 pairings). Beyond, Student's t approximation.
constexpr std::size_t kExactRankTestUpTo = 9;

double rankCorrelationP(const std::vector<double>& ra, const std::vector<double>& rb, double rho) {
    const std::size_t n = ra.size();
    if (!std::isfinite(rho) || n < 3) return std::nan("");
    if (n > kExactRankTestUpTo) return pearsonPValue(rho, n);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> permuted(n);
    long atLeast = 0, total = 0;
    do {
        for (std::size_t i = 0; i < n; ++i) permuted[i] = rb[order[i]];
        const double r = pearson(ra, permuted);
        atLeast += std::fabs(r) >= std::fabs(rho) - 1e-12;  // equal up to round-off counts as at least as strong
        ++total;
    } while (std::next_permutation(order.begin(), order.end()));
    return static_cast<double>(atLeast) / total;
}

const StructureAssessment* rowOf(const AssessmentResults& r, const std::string& name, stand::ForestStructure structure) {
    for (const auto& row : r.stands)
        if (row.name == name && row.structure == structure) return &row;
    return nullptr;
}

}  // namespace

ModelComparison compareModels(const AssessmentResults& first, const AssessmentResults& second) {
    if (first.stands.size() != second.stands.size())
        throw std::invalid_argument("compareModels: the two results assess different stands");
    ModelComparison c;
    c.first = &first;
    c.second = &second;
    for (std::size_t i = 0; i < first.stands.size(); ++i) {
        const StructureAssessment& a = first.stands[i];
        const StructureAssessment* b = rowOf(second, a.name, a.structure);
        if (!b) throw std::invalid_argument("compareModels: " + a.name + " " + structureCode(a.structure) + " is in one result only");
        c.stands.push_back({a.name, a.structure, &a, b, a.pf50Ci.low <= b->pf50Ci.high && b->pf50Ci.low <= a.pf50Ci.high});
    }
    for (auto structure : assessedStructures()) {
        std::vector<double> pfFirst, pfSecond;
        for (const auto& s : c.stands)
            if (s.structure == structure) {
                pfFirst.push_back(s.first->pf50);
                pfSecond.push_back(s.second->pf50);
            }
        const auto ra = ranks(pfFirst), rb = ranks(pfSecond);
        StructureModelAgreement agreement{structure, pfFirst.size(), pearson(ra, rb), 0};
        agreement.rankCorrelationP = rankCorrelationP(ra, rb, agreement.rankCorrelation);
        c.agreement.push_back(agreement);
    }
    for (const auto& s : c.stands) {
        if (s.structure != stand::ForestStructure::Aggregated) continue;
        const StructureAssessment* naFirst = rowOf(first, s.name, stand::ForestStructure::Random);
        const StructureAssessment* naSecond = rowOf(second, s.name, stand::ForestStructure::Random);
        if (!naFirst || !naSecond) continue;
        ++c.standsWithBoth;
        c.naAboveA[0] += naFirst->pf50 > s.first->pf50;
        c.naAboveA[1] += naSecond->pf50 > s.second->pf50;
    }
    return c;
}

}  // namespace sylva::assess
