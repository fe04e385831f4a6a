#pragma once
// A stem with every mode excited (random node velocities), stepped on its own: how much its energy
// grew. Shared by the tests of its stable step and of the step taken from a changing bound.
#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "libdem/SimulationError.hpp"
#include "libdem/Stem.hpp"
#include "libdem/StemStepper.hpp"

namespace sylva::dem::testing {

// Steps `stem` `steps` times, step k of length step(k, its stable bound), from random node velocities
// (seeded). Returns its energy's peak over the last tenth of the steps against its peak over the
// first tenth, infinity if it blew up or became NaN. Peaks, because near the limit a leapfrog's
// energy, read with the velocities brought to the step's time, swings by up to
// 1 / (1 - (omega dt / 2)^2) over each period of a stable mode without growing.
inline double stemEnergyGrowth(Stem stem, const std::function<double(int, double)>& step, int steps, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    const auto random = [&] { return Vec3(normal(rng), normal(rng), normal(rng)); };
    for (std::size_t i = 0; i < stem.nodeCount(); ++i) {
        if (stem.translates(i)) stem.velocity[i] = 1e-3 * random();
        if (stem.rotates(i)) stem.angularVelocity[i] = 1e-3 * random();
    }
    StemStepper stepper(Vec3::Zero());
    const double bound = stem.stableTimeStep();
    const int window = steps / 10;
    double start = 0, first = 0, last = 0;
    try {
        for (int k = 0; k < steps; ++k) {
            const double e = stepper.step(stem, step(k, bound)).total();
            if (k == 0) start = e;
            if (!(e < 1e6 * start)) return INFINITY;  // blown up, maybe within the first window
            if (k < window) first = std::max(first, e);
            if (k >= steps - window) last = std::max(last, e);
        }
    } catch (const SimulationError&) {
        return INFINITY;
    }
    return last / first;
}

}  // namespace sylva::dem::testing
