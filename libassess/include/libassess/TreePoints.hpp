#pragma once
// Trees on a DTM for a hazard run: a CSV x,y,dbh_cm (or a sylvarock forest file) in the DTM's CRS, or a
// point layer (GeoPackage, Shapefile, GeoJSON, ...) with a dbh_cm field, its allometry computed from
// the DBH (Eqs. 11-13) as for a CSV without it.
#include <string>

#include "libassess/GeoRaster.hpp"
#include "libstand/Forest.hpp"

namespace sylva::assess {

// InputError naming the file for: unreadable, a layer CRS other than the DTM's, no dbh_cm field, a
// DBH missing, <= 0 or above 200 cm, no point at all (and the CSV reader's own errors).
stand::Forest readTreePoints(const std::string& path, const Dtm& dtm);

}  // namespace sylva::assess
