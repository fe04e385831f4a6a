// Timing of `sylvarock stats` on a virtual-forest-sized pattern: 3600 uniform stems in 1000 m x 500 m,
// statistics (N, G, DBH, Clark-Evans with all corrections) and g(r) with both edge corrections on
// spatstat's default range (rmax = 125 m, 513 values). Prints the median of several runs.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "libstand/Inventory.hpp"
#include "libstand/PairCorrelation.hpp"
#include "libstand/StandStatistics.hpp"

using namespace sylva::stand;

int main() {
    const Window window = Window::rectangle(0, 0, 1000, 500);
    std::mt19937_64 rng(20240607);
    std::uniform_real_distribution<double> ux(0, 1000), uy(0, 500), dbh(5, 60);
    Inventory inv;
    inv.name = "uniform-3600";
    inv.plots.push_back({"1", window});
    std::vector<Eigen::Vector2d> xy;
    for (int i = 0; i < 3600; ++i) {
        Stem s;
        s.plot = "1";
        s.id = std::to_string(i + 1);
        s.x = ux(rng);
        s.y = uy(rng);
        s.dbhCm = dbh(rng);
        xy.emplace_back(s.x, s.y);
        inv.stems.push_back(s);
    }
    const double rmax = defaultPairCorrelationRmax(window, xy.size());
    const int runs = 7;
    std::vector<double> total, pcfOnly;
    double sink = 0;
    for (int k = 0; k < runs; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        const StandStatistics s = standStatistics(inv);
        const auto t1 = std::chrono::steady_clock::now();
        const PairCorrelation g = pairCorrelation(xy, window, rmax, 513);
        const auto t2 = std::chrono::steady_clock::now();
        sink += *s.stand.clarkEvans.donnelly + g.trans[100] + g.iso[100];
        total.push_back(std::chrono::duration<double>(t2 - t0).count());
        pcfOnly.push_back(std::chrono::duration<double>(t2 - t1).count());
    }
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    std::printf("bench_stats: 3600 uniform points in 1000 x 500 m, g(r) to %.1f m (513 values), %d runs\n", rmax, runs);
    std::printf("  statistics + Clark-Evans + g(r): median %.3f s (g(r) alone %.3f s)   [checksum %.6f]\n",
                median(total), median(pcfOnly), sink / runs);
    return 0;
}
