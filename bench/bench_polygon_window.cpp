// Timing of g(r) (both edge corrections) of 60 points in polygon windows of many vertices: a spiky
// star (the worst case: its shifted spikes cross many spikes) and a traced boundary (a GPS-walked plot
// outline: many short edges), each of 1 000 and 5 000 vertices, r to spatstat's default range at 513
// values, as `stats --points ... --window-wkt ... --pcf-out` computes it. Prints medians of 3 runs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "libstand/PairCorrelation.hpp"

using namespace sylva::stand;

namespace {

Window star(int n) {
    std::vector<Eigen::Vector2d> ring;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n, r = k % 2 ? 30 : 50;
        ring.emplace_back(60 + r * std::cos(a), 60 + r * std::sin(a));
    }
    return Window::polygon(ring);
}

Window traced(int n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> noise(-0.2, 0.2);
    std::vector<Eigen::Vector2d> ring;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n, r = 50 + 3 * std::sin(7 * a) + noise(rng);
        ring.emplace_back(60 + r * std::cos(a), 60 + r * std::sin(a));
    }
    return Window::polygon(ring);
}

}  // namespace

int main() {
    std::mt19937_64 rng(20261125);
    std::uniform_real_distribution<double> u(31, 89);
    std::vector<Eigen::Vector2d> points;
    while (points.size() < 60) {  // inside both shapes: within 29 m of the centre
        const Eigen::Vector2d p(u(rng), u(rng));
        if ((p - Eigen::Vector2d(60, 60)).norm() < 29) points.push_back(p);
    }
    struct Case {
        std::string name;
        Window window;
    };
    std::vector<Case> cases;
    for (int n : {1000, 5000}) {
        cases.push_back({"star, " + std::to_string(n) + " vertices", star(n)});
        cases.push_back({"traced, " + std::to_string(n) + " vertices", traced(n, rng)});
    }
    for (const auto& c : cases) {
        std::vector<double> seconds;
        double sink = 0;
        for (int run = 0; run < 3; ++run) {
            const auto t0 = std::chrono::steady_clock::now();
            const PairCorrelation g = pairCorrelation(points, c.window, defaultPairCorrelationRmax(c.window, points.size()), 513);
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
            sink += g.trans[100];
        }
        std::sort(seconds.begin(), seconds.end());
        std::printf("%-24s g(r) of 60 points: median %.3f s (3 runs)   [%g]\n", c.name.c_str(), seconds[1], sink);
    }
}
