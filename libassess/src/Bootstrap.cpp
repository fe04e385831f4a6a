#include "libassess/Bootstrap.hpp"

#include <cmath>
#include <cstdio>

#include <gsl/gsl_rng.h>

#include <stdexcept>

#include "libassess/ProtectionIndex.hpp"
#include "libcommon/SeededRandom.hpp"
#include "libdem/CampaignSummary.hpp"

namespace sylva::assess {

namespace {

void resampleInto(const std::vector<double>& from, gsl_rng* rng, std::vector<double>& to) {
    for (std::size_t i = 0; i < from.size(); ++i) to.push_back(from[gsl_rng_uniform_int(rng, from.size())]);
}
}  // namespace

std::string confidencePercent(double confidence) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", std::round(1e4 * confidence) / 100);
    return text;
}

Interval bootstrapProtectionIndex(const std::vector<std::vector<double>>& realisations, const std::vector<double>& baseline,
                                  const BootstrapSettings& settings) {
    if (realisations.empty() || baseline.empty()) throw std::invalid_argument("bootstrap: no run-outs");
    for (const auto& r : realisations)
        if (r.empty()) throw std::invalid_argument("bootstrap: a realisation without runs");
    if (settings.replicates < 2 || !(settings.confidence > 0 && settings.confidence < 1))
        throw std::invalid_argument("bootstrap: needs at least 2 replicates and a confidence in (0, 1)");
    SeededRandom random(settings.seed);
    gsl_rng* const rng = random.gsl();
    std::vector<double> pf, forest, base;
    pf.reserve(settings.replicates);
    for (int b = 0; b < settings.replicates; ++b) {
        forest.clear();
        base.clear();
        for (std::size_t k = 0; k < realisations.size(); ++k)
            resampleInto(realisations[gsl_rng_uniform_int(rng, realisations.size())], rng, forest);
        resampleInto(baseline, rng, base);
        pf.push_back(protectionIndex(forest, base));
    }
    const double tail = (1 - settings.confidence) / 2;
    return {dem::quantile(pf, tail), dem::quantile(pf, 1 - tail)};
}

}  // namespace sylva::assess
