#include "libassess/HazardMap.hpp"

#include <algorithm>
#include <cmath>

#include "libdem/CampaignSummary.hpp"

namespace sylva::assess {

BlockTrace traceRun(const dem::RunResult& run, const Dtm& dtm, const std::unordered_map<long, Eigen::Vector2d>& treeAt) {
    BlockTrace t;
    t.reason = run.reason;
    const RasterGrid& grid = dtm.grid;
    std::unordered_map<std::uint32_t, std::size_t> seen;  // cell -> its passage
    const auto visit = [&](const Eigen::Vector3d& p, double energyJ) {
        int c = 0, r = 0;
        if (!grid.cellOf(p.x(), p.y(), c, r)) return;
        const double ground = dtm.elevation.height(p.x(), p.y());
        const float height = static_cast<float>(p.z() - ground), energy = static_cast<float>(energyJ / 1000);
        const auto cell = static_cast<std::uint32_t>(grid.index(c, r));
        const auto [it, fresh] = seen.emplace(cell, t.passages.size());
        if (fresh) {
            t.passages.push_back({cell, energy, height});
            return;
        }
        CellPassage& passage = t.passages[it->second];
        passage.energyKj = std::max(passage.energyKj, energy);
        passage.heightM = std::max(passage.heightM, height);
    };
    const auto& samples = run.trajectory;
    const double step = 0.25 * grid.cellSize();
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const auto& b = samples[i];
        const double eb = b.translationalEnergy + b.rotationalEnergy;
        if (i == 0) {
            visit(b.position, eb);
            continue;
        }
        const auto& a = samples[i - 1];
        const double ea = a.translationalEnergy + a.rotationalEnergy;
        const double horizontal = (b.position - a.position).head<2>().norm();
        const int n = std::max(1, static_cast<int>(std::ceil(horizontal / step)));
        for (int k = 1; k <= n; ++k) {
            const double s = static_cast<double>(k) / n;
            visit(a.position + s * (b.position - a.position), ea + s * (eb - ea));
        }
    }
    t.pathLengthM = run.runoutAlongSlope;  // along the ground on a DTM (SurfacePath)
    t.reachM = run.runoutHorizontal;
    int c = 0, r = 0;
    if (run.reason == dem::StopReason::Rest && grid.cellOf(run.stop.x(), run.stop.y(), c, r)) t.depositCell = static_cast<long>(grid.index(c, r));
    for (const auto& impact : run.impacts) {
        const auto tree = treeAt.find(impact.tree);
        if (tree != treeAt.end() && grid.cellOf(tree->second.x(), tree->second.y(), c, r))
            t.impactCells.push_back(static_cast<std::uint32_t>(grid.index(c, r)));
    }
    return t;
}

HazardMap::HazardMap(const RasterGrid& grid)
    : passing_(static_cast<std::size_t>(grid.columns) * grid.rows, 0),
      deposits_(passing_.size(), 0),
      impacts_(passing_.size(), 0),
      energy_(passing_.size()),
      height_(passing_.size()) {}

void HazardMap::add(const BlockTrace& trace) {
    ++blocks_;
    for (const auto& p : trace.passages) {
        passing_[p.cell] += 1;
        energy_[p.cell].push_back(p.energyKj);
        height_[p.cell].push_back(p.heightM);
    }
    if (trace.depositCell >= 0) deposits_[static_cast<std::size_t>(trace.depositCell)] += 1;
    for (auto c : trace.impactCells) impacts_[c] += 1;
}

std::vector<float> HazardMap::passingCount() const { return passing_; }

std::vector<float> HazardMap::reachProbability() const {
    std::vector<float> p(passing_.size(), 0);
    if (blocks_ > 0)
        for (std::size_t i = 0; i < p.size(); ++i) p[i] = static_cast<float>(passing_[i] / static_cast<double>(blocks_));
    return p;
}

std::vector<float> HazardMap::deposits() const { return deposits_; }
std::vector<float> HazardMap::treeImpacts() const { return impacts_; }

namespace {
std::vector<float> p95(const std::vector<std::vector<float>>& values, float noData) {
    std::vector<float> out(values.size(), noData);
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!values[i].empty()) out[i] = static_cast<float>(dem::quantile(std::vector<double>(values[i].begin(), values[i].end()), 0.95));
    return out;
}
}  // namespace

std::vector<float> HazardMap::energyP95Kj(float noData) const { return p95(energy_, noData); }
std::vector<float> HazardMap::heightP95M(float noData) const { return p95(height_, noData); }

}  // namespace sylva::assess
