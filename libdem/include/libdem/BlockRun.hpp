#pragma once
// One block released on the slope and followed until it rests, leaves the domain or runs out of time.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "libdem/ForestLedger.hpp"
#include "libdem/Scene.hpp"
#include "libdem/StemLedger.hpp"
#include "libdem/StepPhases.hpp"

namespace sylva::dem {

class SoilBed;
class SurfacePath;

// Failed: the run stopped on a SimulationError (its message in RunResult::failure); it has no
// run-out and campaigns leave it out of their statistics.
enum class StopReason { Rest, LeftDomain, TimeLimit, Failed };
inline constexpr std::array<StopReason, 4> kStopReasons = {StopReason::Rest, StopReason::LeftDomain, StopReason::TimeLimit,
                                                           StopReason::Failed};
std::string toString(StopReason r);  // "rest", "left_domain", "time_limit", "failed"

struct TrajectorySample {
    double t;
    Vec3 position, velocity, angularVelocity;
    double translationalEnergy, rotationalEnergy;
};

// Where the energy went, J. Closes when initial = kinetic + potential change + stored + dissipated.
struct EnergyBudget {
    double initialTotal = 0;     // kinetic + potential at release (potential relative to z = 0)
    double kinetic = 0, potential = 0, stored = 0;  // at the end
    double contactDamping = 0, friction = 0;        // dissipated
    double imbalance = 0;        // largest |total - initial| seen, relative to the energy converted
    bool flagged = false;        // imbalance above integration.energy_warning: the budget did not close to it
};


// One block/tree impact: what the block had before and after, and what became of the tree.
struct TreeImpact {
    long tree = 0;              // stem id in the forest file
    double time = 0;            // s since release, at first contact
    double speedBefore = 0, speedAfter = 0;    // m/s
    double energyBefore = 0, energyAfter = 0;  // block's kinetic energy, J
    double height = 0;          // above the stem's foot, m
    double eccentricity = 0;    // lateral offset of the block's centre from the stem axis / (r_block + r_stem), in [-1, 1]
    bool stemBroken = false, rootYielded = false, rootFailed = false;
    double breakHeight = std::nan("");  // m above the foot, of the lowest break (NaN: not broken)
    double stemHeight = 0;              // H_T, m: with breakHeight, tells a snapped top from a broken bole
    // Connections of the stem broken when its impact was closed (the stem put to sleep, or the run's
    // end), whatever broke them: an earlier impact on it, a fold past pi / 2, its pieces landing (not
    // if forest.piece_max_time_s let it sleep before). A brittle rupture (Eq. 6) shatters a whipped
    // stem into more pieces the finer its nodes (docs/model-stems.md, "A broken stem shatters").
    std::size_t stemBreaks = 0;
    // What the tree's own terms took from the first contact to the block leaving it (not what its
    // broken pieces dissipate later, falling on the soil), J.
    StemLedger duringImpact;
};

// A stem connection that broke (Eq. 6's rupture, a fracture gone through, or a fold past pi / 2).
struct StemBreak {
    long tree = 0;        // stem id in the forest file
    double time = 0;      // s since release, at the start of the step that broke it
    double height = 0;    // m above the foot, of the connection's middle in the unloaded stem
    double diameter = 0;  // m, D_con: its strength goes with D^3 (Eq. 6), its fracture energy with D^2
};

struct RunResult {
    int run = 0;
    std::uint64_t seed = 0;
    Vec3 release{0, 0, 0}, stop{0, 0, 0};
    double runoutAlongSlope = 0, runoutHorizontal = 0, energyLineDeg = 0;
    StopReason reason = StopReason::TimeLimit;
    double maxSpeed = 0, meanSpeed = 0, maxBounce = 0;
    double duration = 0, cpuSeconds = 0;
    long steps = 0;
    double meanDt = 0;
    PhaseTimes phases;  // where its steps' time went
    NodeSteps nodeSteps;  // its stems' work
    EnergyBudget energy;
    std::vector<TreeImpact> impacts;
    std::vector<StemBreak> breaks;  // every stem's, in the order they broke (RunOptions::recordBreaks)
    ForestLedger forestEnergy;
    std::vector<TrajectorySample> trajectory;  // filled when asked for
    std::string failure;  // StopReason::Failed: what stopped it

    // Where the block stopped and the run-outs that follow: along the path, horizontal, and the
    // energy line's angle (90 degrees for a block that dropped where it was released).
    void setStop(const Vec3& where, const SoilBed& soil, const SurfacePath& path);
};

struct RunOptions {
    bool recordTrajectory = false;
    // Every stem break in RunResult::breaks: a launch's energy.json lists them; a campaign's runs,
    // each breaking tens of connections, need not carry them (nor send them between ranks).
    bool recordBreaks = false;
    // Release above this point (x, y) instead of the scene's release point and range (hazard maps:
    // a point drawn in a release cell); the fall height and the orientation stay the scene's.
    std::optional<Eigen::Vector2d> releaseAt;
};

// Where and how a run's block starts: drawn from the run's seed alone.
struct Release {
    Vec3 position;
    Quat orientation;
    Vec3 velocity = Vec3::Zero();
};
// Throws InputError if the point is outside the terrain. `at`: RunOptions::releaseAt.
Release drawRelease(const Scene& scene, std::uint64_t seed, const std::optional<Eigen::Vector2d>& at = std::nullopt);

// The run's random draws (orientation, release y) come only from `seed`, so a run is the same
// whichever thread runs it. Throws SimulationError on NaN, energy growth or an unstable forced step,
// InputError on an impossible release (outside the terrain, inside the soil).
RunResult simulateBlock(const Scene& scene, int run, std::uint64_t seed, const RunOptions& options = {});
// CPU time of the calling thread, s (what RunResult::cpuSeconds measures).
double threadCpuSeconds();
// The record of a run that stopped on a SimulationError: its release, no run-out (NaN), the message.
RunResult failedRun(const Scene& scene, int run, std::uint64_t seed, const std::string& why);

}  // namespace sylva::dem
