// Speed of the no-forest simulator: N block runs of a scene on T threads (default: the paper's
// scene, 100 runs, 2 threads), repeated R times. Prints the median wall time of a campaign, the
// median CPU time of one run, and the process's peak memory.
//   bench_no_forest [scene.ini] [runs] [threads] [repeats]
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "libdem/Campaign.hpp"
#include "libdem/CampaignSummary.hpp"

using namespace sylva::dem;

int main(int argc, char** argv) {
    const std::string scenePath = argc > 1 ? argv[1] : std::string(SYLVAROCK_DATA_DIR) + "/scenes/no-forest.ini";
    const int runs = argc > 2 ? std::atoi(argv[2]) : 100;
    const int threads = argc > 3 ? std::atoi(argv[3]) : 2;
    const int repeats = argc > 4 ? std::atoi(argv[4]) : 5;

    const auto t0 = std::chrono::steady_clock::now();
    const Scene scene(loadScene(scenePath));
    const double build = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::vector<double> walls, cpus;
    for (int k = 0; k < repeats; ++k) {
        CampaignOptions o;
        o.runs = runs;
        o.threads = threads;
        o.seed = 5 + k;
        const auto t1 = std::chrono::steady_clock::now();
        const auto results = runCampaign(scene, o);
        walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count());
        for (const auto& r : results) cpus.push_back(r.cpuSeconds);
    }
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    std::printf("scene %s: %zu soil spheres, built in %.2f s\n", scenePath.c_str(), scene.soil().size(), build);
    std::printf("%d runs on %d threads, %d repeats: median wall %.2f s per campaign (min %.2f, max %.2f)\n", runs, threads,
                repeats, quantile(walls, 0.5), quantile(walls, 0), quantile(walls, 1));
    std::printf("CPU per run: median %.4f s, p90 %.4f s, max %.4f s\n", quantile(cpus, 0.5), quantile(cpus, 0.9),
                quantile(cpus, 1));
    std::printf("peak resident memory: %.0f MB\n", ru.ru_maxrss / 1024.0);
    return 0;
}
