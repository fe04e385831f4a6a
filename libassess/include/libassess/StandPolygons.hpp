#pragma once
// Stands drawn as polygons on a DTM, each naming an inventory (the PREFIX of PREFIX_stems.csv and
// PREFIX_plots.csv, as `sylvarock assess --stand`) and a structure: libstand generates a virtual forest
// of that stand inside each polygon (aggregated A or random NA, docs/stand.md), and the forests of all
// polygons make the hazard run's forest.
#include <cstdint>
#include <string>
#include <vector>

#include "libassess/GeoRaster.hpp"
#include "libstand/Forest.hpp"
#include "libstand/ForestGenerator.hpp"

namespace sylva::assess {

struct StandPolygon {
    long feature = 0;         // its number in the file, 1-based over all layers
    std::string inventory;    // the prefix as resolved (relative to the working folder or absolute)
    stand::ForestStructure structure = stand::ForestStructure::Aggregated;
    double areaHa = 0;        // on the terrain (the polygon cut to the DTM's cell centres)
    long stems = 0;           // generated in it (after the stems overlapping a neighbour's were dropped)
    std::uint64_t seed = 0;   // of its first part's forest
};

struct StandForest {
    stand::Forest forest;                // every polygon's stems, ids 1..n, stool ids unique
    std::vector<StandPolygon> polygons;  // in the file's order
    std::vector<std::string> notes;      // warnings of the generator, defaults taken, stems dropped at shared borders
};

// The polygons (and multipolygons) of every layer of a vector file in the DTM's CRS. Fields: `stand`
// (required: an inventory prefix, looked up beside the vector file first, then from the working
// folder) and `structure` (A, NA, aggregated or random; absent: A, said in notes). Each polygon is
// cut to the terrain (the rectangle of the DTM's cell centres); its forest is drawn with a seed
// derived from `seed` and its part's number, so the same file and seed give the same forest. Stems of
// a later polygon that would overlap an earlier one's at a shared border are dropped.
// InputError naming the file and the feature for: unreadable file, no polygon, a CRS other than the
// DTM's, a missing or unknown stand, an unknown structure, a polygon outside the terrain, two polygons
// overlapping (by more than 1 m2), the generator's own errors (a polygon too small for a stool), and an
// inventory stem thinner than the stems' tip diameter (m), named by its line.
StandForest readStandPolygons(const std::string& path, const Dtm& dtm, std::uint64_t seed, double tipDiameter);

}  // namespace sylva::assess
