#pragma once
// What no terrain does, which a height read from a file must not either: the DTM's and the slope
// profile's readers refuse such heights as NODATA values left in the data.
#include <algorithm>
#include <cmath>

namespace sylva::dem {

// Earth's relief runs from -10 935 m (the Challenger Deep) to 8 849 m (Everest). A height beyond it
// is a NODATA marker (GDAL's float32 -3.4e38, 1e30): read as terrain, it made a wall kilometres high
// and run-outs of 1e38 m.
inline bool onEarth(double z) { return z >= -11000 && z <= 9000; }
constexpr const char* kEarthsRelief = "Earth's relief (-11 000 to 9 000 m)";

// A NODATA marker within Earth's relief (-9999, -10000) beside real ground makes a step of ~10 km:
// read as terrain, it was a pit where every block stopped (a path of 344 km, a map of blocks at rest,
// no warning) or fell through the soil. No terrain has a step both steeper than 89 degrees and higher
// than 2 000 m between neighbouring cells or profile points (the highest vertical face, Mount Thor's,
// drops 1 250 m), so real cliffs pass, however fine the cells. A marker beside ground at sea level
// is caught on cells of up to 174 m (9 999 m over 57.29 times the cell).
constexpr const char* kImpossibleStep = "a step no terrain has (steeper than 89 degrees and higher than 2 000 m)";
inline bool impossibleStep(double rise, double run) {
    constexpr double kSteepest = 57.29;  // tan(89 degrees)
    constexpr double kHighestFace = 2000;  // m
    return std::abs(rise) > std::max(kHighestFace, kSteepest * std::abs(run));
}

}  // namespace sylva::dem
