// Cost of one stem node-step, the unit a forested run is made of (~70 % of its CPU is stems
// stepping): a 20 cm beech on its root spring, swinging (1 m/s at the top), stepped 20 000 times at
// 0.9 of its stable step, with the default (calibrated) parameters, at each node spacing. The
// workload does not depend on the trajectory a run happens to take, so two builds compare on the
// same work. Prints the median over repeats of nanoseconds per node-step and node-steps per second,
// then each DBH's stable step on its root spring and clamped.
//   bench_stem_step [repeats]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "libdem/CampaignSummary.hpp"
#include "libdem/Stem.hpp"
#include "libdem/StemParameterSet.hpp"
#include "libdem/StemStepper.hpp"

using namespace sylva::dem;

namespace {

constexpr int kSteps = 20000;

// Nanoseconds per node-step of one swing; `energyOut` keeps the work from being optimised away.
double swing(double spacing, double& energyOut) {
    StemParams p = stemParameters(StemParameterSet::Calibrated);
    p.nodeSpacing = spacing;
    Stem stem(beechStem(20), p, Vec3::Zero(), StemFoot::RootSpring);
    const Vec3 gravity(0, 0, -9.81);
    stem.carryOwnWeight(-gravity.z());
    // An unbroken stem swinging after an impact, 1 m/s at the top: every connection works every step.
    const double top = stem.restHeight(stem.nodeCount() - 1);
    for (std::size_t i = 0; i < stem.nodeCount(); ++i)
        if (stem.translates(i)) stem.velocity[i] = Vec3(stem.restHeight(i) / top, 0, 0);
    StemStepper stepper(gravity);
    const double dt = 0.9 * stem.stableTimeStep();
    const auto t0 = std::chrono::steady_clock::now();
    double e = 0;
    for (int k = 0; k < kSteps; ++k) e += stepper.step(stem, dt).total();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!std::isnan(stem.lowestBreakHeight())) std::printf("(the stem broke: not the workload meant)\n");
    energyOut += e;
    return 1e9 * s / (static_cast<double>(kSteps) * static_cast<double>(stem.nodeCount()));
}

}  // namespace

int main(int argc, char** argv) {
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    double sink = 0;
    std::printf("20 cm beech (calibrated set) on its root spring, %d steps at 0.9 of the stable step, median of %d repeats\n",
                kSteps, repeats);
    for (const double spacing : {0.5, 0.25, 0.125}) {
        std::vector<double> ns;
        for (int r = 0; r < repeats; ++r) ns.push_back(swing(spacing, sink));
        const double median = quantile(ns, 0.5);
        std::printf("%.3f m: %6.1f ns per node-step (min %.1f, max %.1f), %.2e node-steps/s\n", spacing, median,
                    quantile(ns, 0), quantile(ns, 1), 1e9 / median);
    }
    // What the foot's root spring costs the step (docs/performance.md, "Where the rest is"): each
    // stem's stable step on its root spring, and how much longer it is with the foot clamped.
    std::printf("stable step at 0.5 m, calibrated set: DBH, on the root spring, clamped / root spring\n");
    const StemParams calibrated = stemParameters(StemParameterSet::Calibrated);
    for (const double dbh : {8.0, 10.0, 15.0, 20.0, 30.0, 40.0}) {
        const double root = Stem(beechStem(dbh), calibrated, Vec3::Zero(), StemFoot::RootSpring).stableTimeStep();
        const double clamped = Stem(beechStem(dbh), calibrated, Vec3::Zero(), StemFoot::Clamped).stableTimeStep();
        std::printf("%4.0f cm: %.3e s, x%.2f\n", dbh, root, clamped / root);
    }
    std::printf("(checksum %.6e)\n", sink);
    return 0;
}
