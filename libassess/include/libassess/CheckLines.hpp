#pragma once
// Check lines for a hazard run: lines drawn on the slope (where a barrier or a road would go) and what
// the blocks had when they crossed them. A barrier is designed on the distribution of the energy, the
// passing height and the speed of the blocks reaching its line, which the rasters (a percentile per
// cell, of each block's largest value in it) do not give.
#include <Eigen/Core>

#include <string>
#include <vector>

#include "libassess/GeoRaster.hpp"
#include "libdem/BlockRun.hpp"

namespace sylva::assess {

struct CheckLine {
    std::string name;
    std::vector<Eigen::Vector2d> vertices;  // a polyline in the DTM's CRS, >= 2 vertices, no two consecutive ones equal
};

// The line (and multiline) features of every layer of a vector file (GeoJSON, GeoPackage, Shapefile,
// ...) read through OGR; layers without lines are passed over, and so are a feature's z and a vertex
// repeating the one before it. name: the feature's field "name" if its layer has one and it is set
// (not empty), else "line <n>" (n counting the line features of the file from 1); each part of a
// multiline is its own CheckLine, "<name> part <k>". InputError naming the file (and the layer and
// feature concerned) for: a file OGR cannot read, no line at all, a layer CRS other than the DTM's, a
// line with fewer than 2 distinct vertices, a line entirely outside the DTM's extent (its cells' outer
// edges), two lines with the same name. `passedOver`, if given, receives how many features of the
// layers holding lines are not lines (a map's points or polygons, which the caller may mention).
std::vector<CheckLine> readCheckLines(const std::string& path, const Dtm& dtm, int* passedOver = nullptr);

struct LineCrossing {
    int line = 0;          // index into the CheckLine vector
    double x = 0, y = 0;   // where the path crossed it (horizontal projection)
    float energyKj = 0;    // kinetic energy (translational + rotational) there, kJ
    float heightM = 0;     // height of the block's centre above the DTM's surface there, m (dtm.elevation.height(x, y))
    float speedMs = 0;     // |velocity| there, m/s
    float time = 0;        // s since release
};

// Each line at most once per block: its first crossing (a barrier there stops the block). The step
// between two consecutive trajectory samples is intersected in plan with each segment of the line,
// the values interpolated linearly between the two samples at the intersection; the speed between
// the samples' speeds, like the energy (a bounce between two samples reverses the velocity, whose
// interpolated vector would pass near zero). A step holds its first sample, not its last: a sample
// exactly on the line is counted once, and a path ending on the line has not crossed it. A step
// parallel to a segment does not cross it. Sorted by line index.
std::vector<LineCrossing> crossCheckLines(const std::vector<dem::TrajectorySample>& samples, const Dtm& dtm,
                                          const std::vector<CheckLine>& lines);

// Accumulates the crossings of the passes of a hazard run ("forest", "bare") and writes them.
class CheckLineTally {
public:
    explicit CheckLineTally(std::vector<CheckLine> lines);
    // Runs of a pass in increasing order (the rows' order does not then depend on the threads);
    // std::logic_error for a run not after the pass's previous one, or a crossing of no line.
    void add(const std::string& pass, long run, const std::vector<LineCrossing>& crossings);
    // The blocks of the pass (its runs that did not fail): what the fractions are of.
    void setBlocks(const std::string& pass, long blocks);
    // In `dir` (which exists), passes in the order they were first named (add or setBlocks), lines in
    // their order, runs increasing:
    //   check_lines.csv: pass,line,run,x,y,time_s,energy_kj,height_m,speed_m_s, one row per crossing;
    //   check_lines_summary.csv: pass,line,blocks,crossings,fraction,energy_kj_p50,energy_kj_p95,
    //     energy_kj_p99,height_m_p50,height_m_p95,height_m_p99,speed_m_s_p50,speed_m_s_p95,speed_m_s_p99,
    //     a row per pass and line: blocks of the pass, crossings = blocks that crossed the line,
    //     fraction = crossings / blocks, percentiles with dem::quantile (GSL's linear interpolation);
    //     empty fields where there is no value (no crossing, no block).
    // x and y with 3 decimals (projected coordinates are ~1e6 m), other numbers with 6 significant
    // digits. InputError naming the file if it cannot be written; std::logic_error for a pass
    // without setBlocks.
    void write(const std::string& dir) const;

    // What crossed one line in one pass, for the figure (HazardFigure.hpp).
    struct LineSample {
        std::string pass, line;
        long blocks = 0;                     // of the pass
        std::vector<float> energyKj, heightM;  // of each block that crossed, in run order
    };
    // Passes in the order they were first named, lines in their order.
    std::vector<LineSample> samples() const;

private:
    struct Row {
        long run;
        LineCrossing crossing;
    };
    struct Pass {
        std::string name;
        long blocks = -1;   // -1: not given yet
        long lastRun = -1;  // -1: no run added yet
        std::vector<std::vector<Row>> byLine;
    };
    Pass& passNamed(const std::string& name);  // added on first mention

    std::vector<CheckLine> lines_;
    std::vector<Pass> passes_;
};

}  // namespace sylva::assess
