#pragma once
// Virtual forests over a slope from a stand's inventory (paper Sect. 2.2.2), the algorithm and its
// choices are in docs/stand.md, "Virtual forests":
//  - Aggregated (A): stool centroids uniform in the extent (a Poisson process conditioned on its
//    count, stools/ha of the inventory), each stool a whole inventory stool (offsets, rotated at
//    random, diameters, species), then single trees drawn from the inventory's single trees, placed
//    uniformly, until the stand's N is reached.
//  - Random (NA): every stem uniform in the extent, diameters drawn from all the inventory's stems.
// No stem comes closer to another than r_i + r_j + clearance. Diameters are resampled "by whole
// copies" of the inventory, so N is exact and the diameter mean/sd stay at the inventory's.
#include <string>
#include <vector>

#include "libstand/Forest.hpp"
#include "libstand/StandCatalogue.hpp"
#include "libstand/Window.hpp"

namespace sylva::stand {

enum class ForestStructure { Aggregated, Random };

// "aggregated" (or "A") and "random" (or "NA"); throws InputError listing the accepted names.
ForestStructure parseForestStructure(const std::string& name);
std::string toString(ForestStructure structure);

struct GenerationSettings {
    ForestStructure structure = ForestStructure::Aggregated;
    unsigned long seed = 1;      // seeds GSL's mt19937; the same seed gives the same forest
    double clearanceM = 0.01;    // gap between stem surfaces, the rule the inventories follow
    long maxAttempts = 100000;   // random positions tried for one stem or stool before giving up
};

struct GeneratedForest {
    Forest forest;                      // stems 1..n, stool ids 1..k, allometry filled in
    std::size_t stools = 0;             // number of stools written
    std::size_t stemsInStools = 0;
    std::vector<std::string> warnings;  // e.g. "aggregated asked for a stand without stools"
    std::string tooSmall;               // why the extent holds no stem at the stand's density (also a warning); empty if it holds one
};

// Largest forest generated: 2e7 stems (~2 GB as a Scene's stems; a 200 km2 forest at 1 000 stems/ha).
inline constexpr double kMaxGeneratedStems = 2e7;

// The stand's N times the extent's area (rounded) stems over `extent` (x, y in metres). Throws
// InputError if a stem or stool cannot be placed without overlap within maxAttempts tries (the
// extent is too small for a stool or too full for the stand's density).
GeneratedForest generateForest(const StandCatalogue& stand, const Window& extent, const GenerationSettings& settings);

}  // namespace sylva::stand
