#include "libstand/PairCorrelation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <unordered_map>

#include "libstand/EdgeCorrection.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/NearestNeighbours.hpp"

namespace sylva::stand {

PairCorrelation pairCorrelation(const std::vector<Eigen::Vector2d>& points, const Window& window, double rmax,
                                std::size_t nr, const PairCorrelationOptions& options) {
    if (!(rmax > 0) || nr < 2)
        throw InputError("pair correlation: need rmax > 0 and at least 2 distances (got rmax " + std::to_string(rmax) +
                         ", " + std::to_string(nr) + " distances)");
    PairCorrelation g;
    for (std::size_t i = 0; i < nr; ++i)
        g.r.push_back(i + 1 == nr ? rmax : static_cast<double>(i) * (rmax / static_cast<double>(nr - 1)));
    const double n = static_cast<double>(points.size());
    if (points.size() < 2) {
        g.trans.assign(nr, std::numeric_limits<double>::quiet_NaN());
        g.iso = g.trans;
        return g;
    }
    const double lambda = n / window.area();
    g.bandwidth = options.stoyan / std::sqrt(lambda);
    const double sd = g.bandwidth / std::sqrt(5.0);  // the kernel's standard deviation, R's "bw"

    const std::vector<ClosePair> pairs = closePairs(points, rmax + g.bandwidth);
    const TranslationCorrection translation(window);
    std::vector<double> d, wTrans, wIso;
    d.reserve(pairs.size());
    wTrans.reserve(pairs.size());
    wIso.reserve(pairs.size());
    // The pairs are listed both ways, and |W ∩ (W + v)| = |W ∩ (W - v)|: one set covariance per pair.
    std::unordered_map<std::uint64_t, double> translationOfPair;
    for (const auto& p : pairs) {
        d.push_back(p.distance);
        const std::uint64_t key = std::min(p.i, p.j) * points.size() + std::max(p.i, p.j);
        const auto [it, fresh] = translationOfPair.try_emplace(key, 0.0);
        if (fresh) it->second = translation.weight(points[p.j] - points[p.i]);
        wTrans.push_back(it->second);
        wIso.push_back(isotropicWeight(window, points[p.i], p.distance));
    }
    const auto smooth = [&](const std::vector<double>& w) {
        std::vector<double> f = epanechnikovSum(d, w, sd, 0.0, rmax, nr, options.kernelSum);
        const double pairsPerArea = n * (n - 1) / window.area();
        for (std::size_t i = 0; i < nr; ++i) f[i] = f[i] / g.r[i] / (2 * M_PI * pairsPerArea);  // divisor "r"
        return f;
    };
    g.trans = smooth(wTrans);
    g.iso = smooth(wIso);
    return g;
}

double defaultPairCorrelationRmax(const Window& window, std::size_t nPoints) {
    const Eigen::Vector2d frame = window.upper() - window.lower();
    const double ripley = frame.minCoeff() / 4;
    if (nPoints == 0) return ripley;
    const double lambda = static_cast<double>(nPoints) / window.area();
    return std::min(ripley, std::sqrt(1000 / (M_PI * lambda)));
}

PairCorrelation poolPairCorrelations(const std::vector<PairCorrelation>& estimates, const std::vector<double>& weights) {
    if (estimates.empty() || estimates.size() != weights.size())
        throw InputError("pooling pair correlations: need one weight per estimate");
    PairCorrelation pooled;
    pooled.r = estimates.front().r;
    const std::size_t nr = pooled.r.size();
    pooled.trans.assign(nr, 0.0);
    pooled.iso.assign(nr, 0.0);
    double total = 0, bandwidth = 0;
    for (std::size_t k = 0; k < estimates.size(); ++k) {
        if (estimates[k].r != pooled.r) throw InputError("pooling pair correlations: the r grids differ");
        if (weights[k] <= 0) continue;
        for (std::size_t i = 0; i < nr; ++i) {
            pooled.trans[i] += weights[k] * estimates[k].trans[i];
            pooled.iso[i] += weights[k] * estimates[k].iso[i];
        }
        bandwidth += weights[k] * estimates[k].bandwidth;
        total += weights[k];
    }
    for (std::size_t i = 0; i < nr; ++i) {
        pooled.trans[i] = total > 0 ? pooled.trans[i] / total : std::numeric_limits<double>::quiet_NaN();
        pooled.iso[i] = total > 0 ? pooled.iso[i] / total : std::numeric_limits<double>::quiet_NaN();
    }
    pooled.bandwidth = total > 0 ? bandwidth / total : 0;
    return pooled;
}

std::vector<PlotPoints> plotPoints(const Inventory& inventory) {
    std::vector<PlotPoints> plots;
    std::map<std::string, std::size_t> index;
    for (const auto& p : inventory.plots) {
        index[p.id] = plots.size();
        plots.push_back({p.window, {}});
    }
    for (const auto& s : inventory.stems) plots[index.at(s.plot)].points.emplace_back(s.x, s.y);
    return plots;
}

double defaultPairCorrelationRmax(const std::vector<PlotPoints>& plots) {
    double rmax = std::numeric_limits<double>::infinity(), any = rmax;
    for (const auto& p : plots) {
        const double r = defaultPairCorrelationRmax(p.window, p.points.size());
        any = std::min(any, r);
        if (holdsAPair(p)) rmax = std::min(rmax, r);
    }
    return std::isfinite(rmax) ? rmax : any;
}

PairCorrelation pooledPairCorrelation(const std::vector<PlotPoints>& plots, double rmax, std::size_t nr,
                                      const PairCorrelationOptions& options) {
    std::vector<PairCorrelation> estimates;
    std::vector<double> weights;
    for (const auto& p : plots) {
        estimates.push_back(pairCorrelation(p.points, p.window, rmax, nr, options));
        weights.push_back(static_cast<double>(p.points.size()) * (static_cast<double>(p.points.size()) - 1));
    }
    return poolPairCorrelations(estimates, weights);
}

}  // namespace sylva::stand
