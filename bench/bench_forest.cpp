// Speed of forested runs (issue 4's target: 100 runs through a 500 m x 200 m forest at ~2 000
// stems/ha in under 2 minutes on 2 cores, under 1 GB). Generates the MO1 aggregated forest of the
// outside check (extent 130,0,630,200, seed 3), then runs the same campaign with and without it on
// the paper's scene: the ratio of the two is what the forest costs, and where the forested steps'
// time goes, phase by phase.
//   bench_forest [runs] [threads] [seed] [section.key=value ...]
// The scene keys after the seed change the forested and the bare scene alike (the stems' options,
// e.g. stem.upper_spacing_factor=2), as simulate's --set does.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "libdem/Campaign.hpp"
#include "libdem/CampaignSummary.hpp"
#include "libstand/ForestGenerator.hpp"
#include "libstand/Inventory.hpp"

using namespace sylva;

namespace {

struct Timing {
    double wall = 0;
    std::vector<double> cpu, runout;
    long impacts = 0;
    dem::PhaseTimes phases;
    dem::NodeSteps nodeSteps;
};

Timing timeCampaign(const dem::Scene& scene, int runs, int threads, unsigned long seed) {
    dem::CampaignOptions o;
    o.runs = runs;
    o.threads = threads;
    o.seed = seed;
    const auto t0 = std::chrono::steady_clock::now();
    const auto results = dem::runCampaign(scene, o);
    Timing t;
    t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (const auto& r : results) {
        t.cpu.push_back(r.cpuSeconds);
        t.runout.push_back(r.runoutAlongSlope);
        t.impacts += static_cast<long>(r.impacts.size());
        t.phases += r.phases;
        t.nodeSteps += r.nodeSteps;
    }
    return t;
}

// A positional count: the whole argument a whole number >= `least`, or the bench stops naming it (a
// scene key given in its place was read as 0 by atoi, and the bench ran 0 runs).
unsigned long positional(const char* text, const char* name, unsigned long least) {
    const std::string t = text;
    std::size_t used = 0;
    unsigned long v = 0;
    try {
        if (!t.empty() && t[0] != '-') v = std::stoul(t, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != t.size() || v < least)
        throw std::invalid_argument("the " + std::string(name) + " '" + t + "' is not a whole number >= " + std::to_string(least) +
                                    " (bench_forest [runs] [threads] [seed] [section.key=value ...])");
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 100, threads = 2;
    unsigned long seed = 9;
    dem::SceneConfig config;
    const std::string data = SYLVAROCK_DATA_DIR;
    // The positional counts end at the first scene key.
    int keys = 1;
    while (keys < std::min(argc, 4) && !std::strchr(argv[keys], '=')) ++keys;
    const std::vector<std::string> overrides(argv + keys, argv + argc);
    try {
        if (keys > 1) runs = static_cast<int>(positional(argv[1], "run count", 1));
        if (keys > 2) threads = static_cast<int>(positional(argv[2], "thread count", 1));
        if (keys > 3) seed = positional(argv[3], "seed", 0);
        config = dem::loadScene(data + "/scenes/no-forest.ini", overrides);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_forest: %s\n", e.what());
        return 2;
    }

    const std::string stems = data + "/stands/MO1_stems.csv";
    const stand::StandCatalogue stand(stand::readInventory(stems, data + "/stands/MO1_plots.csv"), stems);
    stand::GenerationSettings g;
    g.seed = 3;
    auto forest = stand::generateForest(stand, stand::Window::rectangle(130, 0, 630, 200), g).forest;
    const std::size_t stemCount = forest.trees.size();
    std::optional<dem::Scene> bare, forested;
    try {  // a key may make the forest unbuildable (a tip diameter above its thinnest stems)
        bare.emplace(config);
        forested.emplace(config, std::move(forest));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_forest: %s\n", e.what());
        return 2;
    }

    const Timing without = timeCampaign(*bare, runs, threads, seed);
    const Timing with = timeCampaign(*forested, runs, threads, seed);
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);

    std::printf("MO1 aggregated, %zu stems over 10 ha; %d runs on %d threads, seed %lu", stemCount, runs, threads, seed);
    for (const auto& o : overrides) std::printf(", %s", o.c_str());
    std::printf("\n");
    std::printf("%-10s %10s %14s %14s %10s %9s\n", "", "wall s", "CPU/run med s", "CPU/run p90 s", "Dist50 m", "impacts");
    for (const auto& [name, t] : {std::pair<const char*, const Timing&>{"no forest", without}, {"forest", with}})
        std::printf("%-10s %10.1f %14.3f %14.3f %10.1f %9ld\n", name, t.wall, dem::quantile(t.cpu, 0.5),
                    dem::quantile(t.cpu, 0.9), dem::quantile(t.runout, 0.5), t.impacts);
    std::printf("forest / no forest: wall x%.0f; PF50 on these runs %.3f\n", with.wall / without.wall,
                1 - dem::quantile(with.runout, 0.5) / dem::quantile(without.runout, 0.5));
    std::printf("where a forested step's time goes (share of the steps' time, %.1f s in all):\n", with.phases.total());
    for (std::size_t p = 0; p < dem::kStepPhases; ++p)
        std::printf("  %-20s %5.1f %%\n", dem::name(static_cast<dem::StepPhase>(p)),
                    100 * with.phases.seconds[p] / with.phases.total());
    const double cpu = std::accumulate(with.cpu.begin(), with.cpu.end(), 0.0);
    const double steps = std::max<double>(1, double(with.nodeSteps.total()));
    std::printf("stem node-steps: %.3g, %.2f million per CPU second of the runs; by what kept the stem awake:\n", steps,
                steps / cpu / 1e6);
    for (std::size_t r = 0; r < dem::kStemAwakeReasons; ++r)
        std::printf("  %-32s %5.1f %%\n", dem::name(static_cast<dem::StemAwake>(r)), 100.0 * with.nodeSteps.byReason[r] / steps);
    std::printf("  ... of which broken stems (a connection or the root plate gone) %.1f %%, stems on the soil or\n"
                "      against a neighbour %.1f %%\n",
                100.0 * with.nodeSteps.broken / steps, 100.0 * with.nodeSteps.onSoilOrStem / steps);
    std::printf("peak resident memory: %.0f MB\n", ru.ru_maxrss / 1024.0);
    return 0;
}
