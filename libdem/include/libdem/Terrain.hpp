#pragma once
// The ground: a macroscopic surface (a slope profile extruded across the slope, or a DTM) covered
// with fixed soil spheres that give it its roughness (paper Sect. 2.1.1, 2.2.1, Figs. 6-7).
// One header per class; this one includes them all.
#include "libdem/ElevationGrid.hpp"
#include "libdem/SlopeProfile.hpp"
#include "libdem/SoilBed.hpp"
