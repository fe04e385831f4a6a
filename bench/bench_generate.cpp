// How long `sylvarock generate` takes for a 10 ha forest (500 m x 200 m) of a dense stand: SP3
// (2552 stems/ha) and MO2 (2508 stems/ha), aggregated and random. Prints the median of 9 runs.
// usage: bench_generate [DATA_DIR]   (default: the data/stands folder of this source tree)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "libstand/ForestGenerator.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Inventory.hpp"

using namespace sylva::stand;

int main(int argc, char** argv) {
    const std::string source = __FILE__;
    const std::string dataDir =
        argc > 1 ? argv[1] : source.substr(0, source.find_last_of('/')) + "/../data/stands";
    const Window extent = Window::rectangle(0, 0, 500, 200);
    constexpr int kRuns = 9;
    try {
        for (const std::string stand : {"SP3", "MO2"}) {
            const std::string stems = dataDir + "/" + stand + "_stems.csv";
            const StandCatalogue catalogue(readInventory(stems, dataDir + "/" + stand + "_plots.csv"), stems);
            for (ForestStructure structure : {ForestStructure::Aggregated, ForestStructure::Random}) {
                std::vector<double> seconds;
                std::size_t n = 0;
                for (int run = 0; run < kRuns; ++run) {
                    GenerationSettings settings;
                    settings.structure = structure;
                    settings.seed = static_cast<unsigned long>(run + 1);
                    const auto t0 = std::chrono::steady_clock::now();
                    n = generateForest(catalogue, extent, settings).forest.trees.size();
                    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                }
                std::sort(seconds.begin(), seconds.end());
                std::printf("%s %-10s 10 ha, %zu stems: median %.4f s (min %.4f, max %.4f) over %d runs\n", stand.c_str(),
                            toString(structure).c_str(), n, seconds[kRuns / 2], seconds.front(), seconds.back(), kRuns);
            }
        }
    } catch (const sylva::InputError& e) {
        std::fprintf(stderr, "bench_generate: %s\n", e.what());
        return 2;
    }
    return 0;
}
