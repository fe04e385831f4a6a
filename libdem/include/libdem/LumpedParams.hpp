#pragma once
// How near a stem the block's path must pass to hit it.
enum class TreeReach {
    Block,   // the paper's Sect. 2.3.1: centre within R + DBH/2 of the stem's axis
    Centre,  // the block's centre crossing the stem's disc (DBH/2): Rockyfor3D's C code before v6.0
};

// Parameters of the lumped-mass model (the paper's second model, Sect. 2.3.1, after Rockyfor3D):
// the [lumped] section of a scene. Sources and equations: docs/lumped.md.
namespace sylva::dem {

struct LumpedParams {
    // Rockyfor3D soil type 0-7 (Table 1: 4, talus slope): sets the mean normal restitution R_n.
    int soilType = 4;
    // Mean obstacle heights met by 70, 20 and 10 % of the rebounds, m (Table 1: a roughness of 0.04).
    double rg70 = 0.04, rg20 = 0.04, rg10 = 0.04;
    // Horizontal baseline of the finite differences giving the slope under a rebound, m: below the
    // terrain's own resolution (profile points or DTM cells, 2 m in Table 1) it is the facet's normal.
    double slopeBaseline = 0.2;
    // Standard deviation of the random turn of the direction about the slope's normal at a rebound, deg.
    double deviationSdDeg = 4;
    // A block whose speed falls below this has stopped, m/s.
    double stopSpeed = 0.5;
    // Scales every tree's energy capacity (1: Dorren & Berger 2006 as published).
    double treeEnergyScale = 1.0;
    TreeReach treeReach = TreeReach::Block;
};

// Mean normal restitution of a Rockyfor3D soil type and the half-width of its range.
struct SoilRestitution {
    double mean, halfRange;
    const char* description;
};
// Throws std::invalid_argument for a type outside 0-7.
SoilRestitution soilRestitution(int soilType);

}  // namespace sylva::dem
