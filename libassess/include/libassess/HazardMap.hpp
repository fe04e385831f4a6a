#pragma once
// What the blocks of a hazard run did to each cell of the DTM's grid: how many passed through it, how
// many stopped in it, the energy and the passing height of those that passed (their 95th
// percentile), and the tree impacts in it; the rasters sylvarock hazard writes (docs/hazard.md).
#include <string>
#include <unordered_map>
#include <vector>

#include "libassess/GeoRaster.hpp"
#include "libdem/BlockRun.hpp"

namespace sylva::assess {

// One block's passage over the grid: each cell it crossed once, with the most it had there.
struct CellPassage {
    std::uint32_t cell = 0;  // RasterGrid::index
    float energyKj = 0;      // largest kinetic energy (translation + rotation) in the cell, kJ
    float heightM = 0;       // largest height of the block's centre above the ground in the cell, m
};

struct BlockTrace {
    std::vector<CellPassage> passages;   // in the order the block first entered them
    long depositCell = -1;               // where it came to rest (-1: it did not, or off the grid)
    std::vector<std::uint32_t> impactCells;  // the cell of each tree it hit
    double pathLengthM = 0;              // length of its path along the ground, release to stop (RunResult::runoutAlongSlope)
    double reachM = 0;                   // horizontal distance from release to stop
    dem::StopReason reason = dem::StopReason::TimeLimit;
};

// The trace of a run recorded with RunOptions::recordTrajectory. Between two samples the path is
// walked in steps of a quarter cell, so no cell it crossed is missed for samples up to a few cells
// apart; the height above the ground is taken from `dtm` at each step. `treeAt`: each stem id's (x, y).
BlockTrace traceRun(const dem::RunResult& run, const Dtm& dtm, const std::unordered_map<long, Eigen::Vector2d>& treeAt);

class HazardMap {
public:
    explicit HazardMap(const RasterGrid& grid);
    // The rasters are counts and percentiles: they do not depend on the order traces are added in.
    void add(const BlockTrace& trace);
    long blocks() const { return blocks_; }

    // Per cell, row-major from the north-west; `noData` where the statistic has no value (no block
    // passed) or the DTM has none.
    std::vector<float> passingCount() const;
    std::vector<float> reachProbability() const;  // passing count / blocks
    std::vector<float> deposits() const;
    std::vector<float> treeImpacts() const;
    std::vector<float> energyP95Kj(float noData) const;
    std::vector<float> heightP95M(float noData) const;

private:
    long blocks_ = 0;
    std::vector<float> passing_, deposits_, impacts_;
    std::vector<std::vector<float>> energy_, height_;  // per cell, one value per block that passed
};

}  // namespace sylva::assess
