#include "libstand/StandStatistics.hpp"

#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace sylva::stand {
namespace {

DendrometricStatistics dendrometrics(const std::vector<const Stem*>& stems, double areaM2, bool hasDiameters) {
    DendrometricStatistics s;
    s.n = stems.size();
    s.areaHa = areaM2 / 1e4;
    const double n = static_cast<double>(s.n);
    s.stemsPerHa = n / s.areaHa;
    if (hasDiameters) {
        double basal = 0, sum = 0, count = 0;
        std::size_t unknown = 0;
        for (const Stem* t : stems) {
            if (!measured(*t)) {  // below breast height or not measured (the warnings count them)
                unknown += t->dbhCm == 0 ? 0 : 1;
                continue;
            }
            basal += M_PI * (t->dbhCm / 200) * (t->dbhCm / 200);  // m², dbh in cm
            sum += t->dbhCm;
            ++count;
        }
        // Stems below breast height add nothing to G; stems whose DBH is unknown leave it unknown
        // unless some were measured (then G is theirs, as the warnings say).
        if (count > 0 || unknown == 0) s.basalAreaM2Ha = basal / s.areaHa;
        if (count > 0) s.meanDbhCm = sum / count;
        if (count > 1) {
            double ss = 0;
            for (const Stem* t : stems)
                if (measured(*t)) ss += (t->dbhCm - *s.meanDbhCm) * (t->dbhCm - *s.meanDbhCm);
            s.sdDbhCm = std::sqrt(ss / (count - 1));
        }
    }
    std::set<std::pair<std::string, std::string>> stools;  // a stool is its id within its plot
    std::size_t inStools = 0;
    for (const Stem* t : stems)
        if (t->stool) {
            stools.insert({t->plot, *t->stool});
            ++inStools;
        }
    s.nStools = stools.size();
    if (s.nStools > 0) s.stemsPerStool = static_cast<double>(inStools) / static_cast<double>(s.nStools);
    if (s.n > 0) s.stoolShare = static_cast<double>(inStools) / n;
    return s;
}

// Mean of the defined values; counts them.
void accumulate(std::optional<double>& mean, std::size_t& count, const std::optional<double>& value) {
    if (!value) return;
    mean = mean.value_or(0) + *value;
    ++count;
}

}  // namespace

StandStatistics standStatistics(const Inventory& inventory) {
    StandStatistics out;
    out.name = inventory.name;
    std::map<std::string, std::vector<const Stem*>> byPlot;
    std::vector<const Stem*> all;
    for (const auto& s : inventory.stems) {
        byPlot[s.plot].push_back(&s);
        all.push_back(&s);
    }
    ClarkEvansIndex ce;
    double meanNn = 0;
    for (const auto& plot : inventory.plots) {
        const auto& stems = byPlot[plot.id];
        PlotStatistics p;
        p.id = plot.id;
        p.window = plot.window.describe();
        p.empty = stems.empty();
        p.stats = dendrometrics(stems, plot.window.area(), inventory.hasDiameters);
        std::vector<Eigen::Vector2d> xy;
        for (const Stem* s : stems) xy.emplace_back(s->x, s->y);
        p.stats.clarkEvans = clarkEvans(xy, plot.window);
        accumulate(ce.naive, out.plotsInNaiveMean, p.stats.clarkEvans.naive);
        accumulate(ce.donnelly, out.plotsInDonnellyMean, p.stats.clarkEvans.donnelly);
        accumulate(ce.guard, out.plotsInGuardMean, p.stats.clarkEvans.guard);
        accumulate(ce.cdf, out.plotsInCdfMean, p.stats.clarkEvans.cdf);
        if (p.stats.clarkEvans.naive) meanNn += p.stats.clarkEvans.meanNearestNeighbour;
        out.plots.push_back(std::move(p));
    }
    if (ce.naive) *ce.naive /= static_cast<double>(out.plotsInNaiveMean);
    if (ce.donnelly) *ce.donnelly /= static_cast<double>(out.plotsInDonnellyMean);
    if (ce.guard) *ce.guard /= static_cast<double>(out.plotsInGuardMean);
    if (ce.cdf) *ce.cdf /= static_cast<double>(out.plotsInCdfMean);
    if (out.plotsInNaiveMean > 0) ce.meanNearestNeighbour = meanNn / static_cast<double>(out.plotsInNaiveMean);
    out.stand = dendrometrics(all, inventory.areaHa() * 1e4, inventory.hasDiameters);
    out.stand.clarkEvans = ce;
    return out;
}

}  // namespace sylva::stand
