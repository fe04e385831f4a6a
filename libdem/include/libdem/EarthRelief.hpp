#pragma once
// What no terrain does, which a height read from a file must not either: the DTM's and the slope
// profile's readers refuse such heights as NODATA values left in the data.

namespace sylva::dem {

// Earth's relief runs from -10 935 m (the Challenger Deep) to 8 849 m (Everest). A height beyond it
// is a NODATA marker (GDAL's float32 -3.4e38, 1e30): read as terrain, it made a wall kilometres high
// and run-outs of 1e38 m.
inline bool onEarth(double z) { return z >= -11000 && z <= 9000; }

// No terrain face is steeper than 89 degrees over a whole DTM cell or profile segment (a cliff spreads
// over several), but a NODATA marker within Earth's relief (-9999, -10000) beside real ground is:
// read as terrain, it was a pit kilometres deep where every block stopped (a path of 344 km, a map of
// blocks at rest, no warning) or fell through the soil.
constexpr double kSteepestRise = 57.29;  // tan(89 degrees): height over horizontal distance

}  // namespace sylva::dem
