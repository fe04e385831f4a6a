#include "libdem/BlockRun.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "libdem/BlockMotion.hpp"
#include "libdem/SurfacePath.hpp"
#include "libcommon/SeededRandom.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::dem {

std::string toString(StopReason r) {
    switch (r) {
        case StopReason::Rest: return "rest";
        case StopReason::LeftDomain: return "left_domain";
        case StopReason::TimeLimit: return "time_limit";
        case StopReason::Failed: return "failed";
    }
    return "?";
}

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

namespace {

TrajectorySample sample(const RigidBody& b, double t) {
    const double et = 0.5 * b.mass() * b.velocity.squaredNorm();
    return {t, b.position, b.velocity, b.angularVelocity(), et, b.kineticEnergy() - et};
}

// A block is at rest once its centre has stayed within `restDistance` of one point for `restTime`.
// A displacement test, not a speed test: a block rocking on a bump by a millimetre keeps a small
// residual spin for minutes, yet it has stopped.
class RestDetector {
public:
    RestDetector(double distance, double time) : distance_(distance), time_(time) {}
    bool update(const Vec3& p, double t) {
        if (!anchored_ || (p - anchor_).norm() > distance_) {
            anchor_ = p;
            since_ = t;
            anchored_ = true;
        }
        return t - since_ >= time_;
    }

private:
    double distance_, time_;
    bool anchored_ = false;
    Vec3 anchor_{0, 0, 0};
    double since_ = 0;
};

}  // namespace

Release drawRelease(const Scene& scene, std::uint64_t seed, const std::optional<Eigen::Vector2d>& at) {
    SeededRandom rng(seed);
    const auto& cfg = scene.config();
    const auto& rel = cfg.release;
    Quat q = Quat::Identity();
    if (rel.randomOrientation) {
        const double ax = rng.uniform(0, M_PI), ay = rng.uniform(0, M_PI), az = rng.uniform(0, M_PI);
        q = Eigen::AngleAxisd(az, Vec3::UnitZ()) * Eigen::AngleAxisd(ay, Vec3::UnitY()) * Eigen::AngleAxisd(ax, Vec3::UnitX());
    }
    const SoilBed& soil = scene.soil();
    // Named by the keys that placed the coordinates that are out; a point given by the caller
    // (--release-at, a hazard cell) by none.
    auto refuseOutside = [&](double x, double y, const std::string& what, const std::string& remedy,
                             std::vector<const char*> xKeys, const std::vector<const char*>& yKeys) {
        const bool xOut = x < soil.xmin() || x > soil.xmax(), yOut = y < soil.ymin() || y > soil.ymax();
        if (!xOut && !yOut) return;
        const std::string message =
            what + " (" + readableNumber(x) + ", " + readableNumber(y) + ") is outside the terrain (" + soil.boundsText() + ")" + remedy;
        if (!xOut) xKeys.clear();
        if (yOut) xKeys.insert(xKeys.end(), yKeys.begin(), yKeys.end());
        // Then the terrain's: a profile or a DTM changed on --set moved the terrain from under an
        // unchanged release, and the file's release line was named.
        if (!xKeys.empty()) {
            if (xOut) xKeys.insert(xKeys.end(), {"terrain.profile", "terrain.dtm"});
            if (yOut) xKeys.insert(xKeys.end(), {"terrain.width_m", "terrain.dtm"});
        }
        throw xKeys.empty() ? InputError(message) : cfg.refusal(xKeys, message);
    };
    if (cfg.launch.enabled) {
        // At the tree, from upslope: the block's centre at the impact height, offset across its path.
        const auto& l = cfg.launch;
        const PlacedTree& t = scene.trees().tree(0);
        const double reach = scene.blockTemplate().boundingRadius() + 0.5 * t.geometry.dbh;
        const Vec3 p(t.foot.x() - l.distance, t.foot.y() + l.eccentricity * reach, t.foot.z() + l.impactHeight);
        refuseOutside(p.x(), p.y(), "the launch start", ": move the tree (tree.x_m, tree.y_m) or shorten block.launch_distance_m",
                      {"tree.x_m", "block.launch_distance_m"}, {"tree.y_m", "block.eccentricity"});
        // The block as it is turned, not its bounding sphere: a cube flying on a face clears the
        // ground from half its edge up (0.40 m for the 0.5 m3 cube, whose bounding radius is 0.54 m).
        double below = 0;  // how far its lowest point reaches below its centre
        for (const ClumpSphere& s : scene.blockTemplate().spheres()) below = std::max(below, s.radius - (q * s.offset).z());
        if (p.z() - below < soil.surfaceHeight(p.x(), p.y()) + 0.01) {
            std::ostringstream os;
            os.precision(3);
            os << "block.impact_height_m = " << l.impactHeight << " m puts the block into the ground: its lowest point is " << below
               << " m below its centre";
            throw cfg.refusal({"block.impact_height_m"}, os.str());
        }
        return {p, q, Vec3(l.speed, 0, 0)};
    }
    if (at) {
        refuseOutside(at->x(), at->y(), "release point", "", {}, {});
        return {Vec3(at->x(), at->y(), soil.surfaceHeight(at->x(), at->y()) + rel.fallHeight), q};
    }
    const double y = rel.yMax > rel.yMin ? rng.uniform(rel.yMin, rel.yMax) : rel.yMin;
    // y: the scene's range if it gives one, else a forest's (Scene's constructor), else release.y_m.
    const bool forestRange = !rel.yRangeGiven && !scene.forest().trees.empty();
    refuseOutside(rel.x, y, "release point", "", {"release.x_m"},
                  rel.yRangeGiven ? std::vector<const char*>{"release.y_min_m", "release.y_max_m", "release.y_m"}
                  : forestRange   ? std::vector<const char*>{"release.forest_y_min_m", "release.forest_y_max_m"}
                                  : std::vector<const char*>{"release.y_m"});
    return {Vec3(rel.x, y, soil.surfaceHeight(rel.x, y) + rel.fallHeight), q};
}

void RunResult::setStop(const Vec3& where, const SoilBed& soil, const SurfacePath& path) {
    stop = where;
    runoutAlongSlope = sylva::dem::runoutAlongSlope(soil, release, stop, path);
    runoutHorizontal = (stop - release).head<2>().norm();
    energyLineDeg = std::atan2(release.z() - stop.z(), runoutHorizontal) * 180 / M_PI;
}

RunResult failedRun(const Scene& scene, int run, std::uint64_t seed, const std::string& why) {
    RunResult r;
    r.run = run;
    r.seed = seed;
    r.release = drawRelease(scene, seed).position;
    const double none = std::nan("");
    r.stop = Vec3::Constant(none);
    r.runoutAlongSlope = r.runoutHorizontal = r.energyLineDeg = none;
    r.reason = StopReason::Failed;
    r.energy.flagged = true;
    r.failure = why;
    return r;
}

RunResult simulateBlock(const Scene& scene, int run, std::uint64_t seed, const RunOptions& options) {
    const SceneConfig& cfg = scene.config();
    const SoilBed& soil = scene.soil();
    RunResult r;
    r.run = run;
    r.seed = seed;
    BlockMotion motion(scene, drawRelease(scene, seed, options.releaseAt));
    const RigidBody& block = motion.block();
    r.release = block.position;
    RestDetector rest(cfg.stop.restDistance, cfg.stop.restTime);
    SurfacePath path(soil, r.release);
    double nextSample = 0, movingTime = 0, movingDistance = 0;
    bool landed = false;
    const double cpu0 = threadCpuSeconds();
    for (;;) {
        if (options.recordTrajectory && motion.time() >= nextSample) {
            r.trajectory.push_back(sample(block, motion.time()));
            nextSample += cfg.trajectoryInterval;
        }
        const double dt = motion.step();
        const double t = motion.time();
        const Vec3& p = block.position;
        const double speed = block.velocity.norm();
        r.maxSpeed = std::max(r.maxSpeed, speed);
        path.moveTo(p);
        landed = landed || motion.touching();
        if (landed) {
            r.maxBounce = std::max(r.maxBounce, motion.clearance());
            movingTime += dt;
            movingDistance += speed * dt;
        }
        if (p.x() < soil.xmin() || p.x() > soil.xmax() || p.y() < soil.ymin() || p.y() > soil.ymax()) {
            r.reason = StopReason::LeftDomain;
            break;
        }
        if (landed && rest.update(p, t)) {
            r.reason = StopReason::Rest;
            movingTime -= cfg.stop.restTime;  // the rest window is not propagation
            break;
        }
        if (t >= cfg.stop.maxTime) {
            r.reason = StopReason::TimeLimit;
            break;
        }
    }
    r.cpuSeconds = threadCpuSeconds() - cpu0;
    if (options.recordTrajectory) r.trajectory.push_back(sample(block, motion.time()));
    r.steps = motion.steps();
    r.phases = motion.phases();
    r.nodeSteps = motion.nodeSteps();
    r.duration = motion.time();
    r.meanDt = r.duration / std::max(1L, r.steps);
    r.meanSpeed = movingTime > 0 ? movingDistance / movingTime : 0;
    r.setStop(block.position, soil, path);
    r.energy = motion.energy();
    r.impacts = motion.forest().finish(block);
    if (options.recordBreaks) r.breaks = motion.forest().breaks();
    r.forestEnergy = motion.forest().ledger();
    return r;
}

}  // namespace sylva::dem
