#pragma once
// Soil types on a DTM for a hazard run: a table of named contact-parameter sets (Eqs. 14-19: K_n,
// K_t/K_n, damping or restitution, friction) and a map placing them, as polygons with a field `soil`
// naming a type or as a raster of the types' codes. Where the map says nothing, the scene's [soil].
#include <memory>
#include <string>
#include <vector>

#include "libassess/GeoRaster.hpp"
#include "libdem/SoilZones.hpp"

namespace sylva::assess {

struct SoilType {
    std::string name;
    long code = 0;  // its value in a soil raster
    dem::SoilContactParams params;
};

// TABLE.csv with columns name,code and any of kn_n_m, kappa, damping_ratio or restitution (not both),
// friction_deg; a parameter not given is the scene's (`sceneSoil`). InputError naming the file, line
// and column for: a missing name or code column, a name or code given twice, "scene" as a name (the
// zone of the scene's own soil), values outside their ranges (K_n > 0, K_t/K_n > 0, damping ratio in
// [0, 1), restitution in (0, 1], friction in [0, 90) degrees).
std::vector<SoilType> readSoilTypes(const std::string& path, const dem::SoilContactParams& sceneSoil);

// The zones on the DTM's grid (one per DTM cell, the type at its centre): zone 0 is the scene's soil,
// zone k the k-th type. `mapPath`: polygons (any vector format, the DTM's CRS) with a field `soil`
// holding a type's name, or a raster (any grid in the DTM's CRS) holding types' codes, NODATA for
// none. InputError naming the file for: a CRS other than the DTM's, no polygon, no field `soil`, a
// name or code not in the table, a cell centre inside two polygons of different types.
std::shared_ptr<dem::SoilZones> readSoilZones(const std::string& mapPath, const std::vector<SoilType>& types, const Dtm& dtm,
                                              const dem::SoilContactParams& sceneSoil);

}  // namespace sylva::assess
