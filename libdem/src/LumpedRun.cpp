#include "libdem/LumpedRun.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "libdem/LumpedRebound.hpp"
#include "libdem/LumpedTreeImpact.hpp"
#include "libdem/SurfacePath.hpp"
#include "libcommon/InputError.hpp"
#include "libcommon/SeededRandom.hpp"

namespace sylva::dem {
namespace {

// The sphere of the block's volume: the lumped model's block.
double sphereRadius(const Scene& scene) {
    return std::cbrt(3 * scene.blockTemplate().mass() / (4 * M_PI * scene.config().block.densityKgM3));
}

// The macroscopic surface under the sphere. Its normal is the slope over `baseline`, as a DTM of
// that resolution sees it (Table 1: 2 m), so that the rebound does not follow every kink of a profile.
class Ground {
public:
    Ground(const SoilBed& soil, double baseline) : soil_(soil), half_(0.5 * baseline) {}
    double height(double x, double y) const { return soil_.surfaceHeight(x, y); }
    Vec3 normal(double x, double y) const {
        const double gx = (height(x + half_, y) - height(x - half_, y)) / (2 * half_);
        const double gy = (height(x, y + half_) - height(x, y - half_)) / (2 * half_);
        return Vec3(-gx, -gy, 1).normalized();
    }

private:
    const SoilBed& soil_;
    double half_;
};

// First time in [0, dt] at which the horizontal track p + v t comes within `reach` of `axis`, or
// a negative number if it does not; `offset` is then the signed distance of the track from the
// axis at its closest approach (left of the direction of travel positive). A track that starts
// within reach touches at once: a block released there, or one that came within reach over the
// stem's top and has since dropped below it, would otherwise pass through the trunk.
double firstTouch(const Vec3& p, const Vec3& v, double dt, const Vec3& axis, double reach, double& offset) {
    const double dx = p.x() - axis.x(), dy = p.y() - axis.y();
    const double a = v.x() * v.x() + v.y() * v.y();
    if (a == 0) return -1;
    offset = (v.x() * dy - v.y() * dx) / std::sqrt(a);
    const double b = dx * v.x() + dy * v.y();  // half the linear coefficient
    const double c = dx * dx + dy * dy - reach * reach;
    if (c <= 0) return 0;
    const double disc = b * b - a * c;
    if (disc < 0) return -1;
    const double t = (-b - std::sqrt(disc)) / a;
    return t < 0 || t > dt ? -1 : t;
}

struct TreeHit {
    double time = -1;
    std::uint32_t tree = 0;
    double offset = 0;
};

}  // namespace

void refuseReleaseInsideTheGround(const Scene& scene) {
    const double radius = sphereRadius(scene), fall = scene.config().release.fallHeight;
    if (fall <= radius)
        throw InputError(scene.config().sourceFile, 0, "the lumped model's block, a sphere of " + readableNumber(std::round(radius * 100) / 100) +
                                                           " m radius (its volume), would start inside the ground at every release: "
                                                           "release.fall_height_m (" + readableNumber(fall) + " m) must exceed it");
}

RunResult simulateLumped(const Scene& scene, int run, std::uint64_t seed, const RunOptions& options) {
    const SceneConfig& cfg = scene.config();
    const LumpedParams& lp = cfg.lumped;
    const SoilBed& soil = scene.soil();
    const double mass = scene.blockTemplate().mass();
    const double radius = sphereRadius(scene);
    const Vec3 gravity(0, 0, -cfg.gravity);
    const Ground ground(soil, lp.slopeBaseline);
    const LumpedRebound rebound(lp, radius);
    const double blockReach = lp.treeReach == TreeReach::Block ? radius : 0;  // added to a stem's DBH/2
    const LumpedTreeImpact treeImpact(lp);

    RunResult r;
    r.run = run;
    r.seed = seed;
    const Release release = drawRelease(scene, seed, options.releaseAt);
    SeededRandom rng(seed ^ 0x6C756D70ULL);  // its own stream: the release draws stay the DEM's
    Vec3 p = release.position, v = release.velocity;
    r.release = p;
    SurfacePath path(soil, r.release);
    double t = 0, movingTime = 0, movingDistance = 0;
    bool landed = false;
    std::vector<std::uint32_t> near, hitTrees;
    auto clearance = [&](const Vec3& q) { return q.z() - radius - ground.height(q.x(), q.y()); };
    // A block starting in the ground landed at once and stopped: a run-out of 0 m, reported as a rest
    // (the DEM refuses such a release; a block of 520 m^3 has a radius of 5 m, the default fall height).
    if (const double c = clearance(p); c <= 0) {
        const auto cm = [](double v) { return readableNumber(std::round(v * 100) / 100); };  // to the centimetre
        throw InputError(cfg.sourceFile, 0, "the block is released inside the ground at (" + cm(p.x()) + ", " + cm(p.y()) + ", " +
                                                cm(p.z()) + "): its sphere of " + cm(radius) + " m radius reaches " + cm(-c) +
                                                " m below the surface: raise release.fall_height_m (or give a smaller block)");
    }
    auto at = [&](double s) { return Vec3(p + v * s + 0.5 * gravity * s * s); };
    auto record = [&] {
        if (options.recordTrajectory)
            r.trajectory.push_back({t, p, v, Vec3::Zero(), 0.5 * mass * v.squaredNorm(), 0});
    };
    const double cpu0 = threadCpuSeconds();
    r.reason = StopReason::TimeLimit;
    while (t < cfg.stop.maxTime) {
        record();
        path.moveTo(p);
        // A sub-step short enough that the track meets the ground (and the trees) only near its end.
        const double c0 = clearance(p);
        const double reachLength = std::clamp(0.5 * c0, 0.05, 1.0);
        const double speed = std::max(v.norm(), std::sqrt(2 * cfg.gravity * reachLength));
        double dt = reachLength / speed;
        Vec3 q = at(dt);
        bool grounded = clearance(q) <= 0;
        if (grounded) {  // bisect the ground crossing
            double lo = 0, hi = dt;
            for (int k = 0; k < 30 && hi - lo > 1e-7; ++k) {
                const double mid = 0.5 * (lo + hi);
                (clearance(at(mid)) > 0 ? lo : hi) = mid;
            }
            dt = hi;
            q = at(dt);
        }
        TreeHit hit;
        if (scene.forested()) {
            const Vec3 mid = 0.5 * (p + q);
            near.clear();
            const double reach = blockReach + 0.5 * scene.trees().thickest();
            scene.trees().near(mid.x(), mid.y(), 0.5 * (q - p).head<2>().norm() + reach, near);
            for (std::uint32_t i : near) {
                if (std::find(hitTrees.begin(), hitTrees.end(), i) != hitTrees.end()) continue;
                const PlacedTree& tree = scene.trees().tree(i);
                double offset = 0;
                const double th = firstTouch(p, v, dt, tree.foot, blockReach + 0.5 * tree.geometry.dbh, offset);
                if (th < 0 || (hit.time >= 0 && th >= hit.time)) continue;
                if (at(th).z() - radius >= tree.foot.z() + tree.geometry.height) continue;  // over the top
                hit = {th, i, offset};
            }
        }
        if (hit.time >= 0) {
            dt = hit.time;
            q = at(dt);
            grounded = false;
        }
        const Vec3 vq = v + gravity * dt;
        if (landed) {
            movingTime += dt;
            movingDistance += (q - p).norm();
            r.maxBounce = std::max(r.maxBounce, clearance(q));
        }
        p = q;
        v = vq;
        t += dt;
        r.maxSpeed = std::max(r.maxSpeed, v.norm());
        if (p.x() < soil.xmin() || p.x() > soil.xmax() || p.y() < soil.ymin() || p.y() > soil.ymax()) {
            r.reason = StopReason::LeftDomain;
            break;
        }
        if (hit.time >= 0) {
            const PlacedTree& tree = scene.trees().tree(hit.tree);
            hitTrees.push_back(hit.tree);
            TreeImpact rec;
            rec.tree = tree.id;
            rec.time = t;
            rec.speedBefore = v.norm();
            rec.energyBefore = 0.5 * mass * v.squaredNorm();
            rec.height = p.z() - tree.foot.z();
            rec.stemHeight = tree.geometry.height;
            rec.eccentricity = hit.offset / (blockReach + 0.5 * tree.geometry.dbh);
            const auto out = treeImpact.apply(v, tree.geometry.dbh, rec.eccentricity, rec.height, mass, rng);
            v = out.velocity;
            rec.speedAfter = v.norm();
            rec.energyAfter = 0.5 * mass * v.squaredNorm();
            rec.stemBroken = out.treeBroken;
            rec.stemBreaks = out.treeBroken ? 1 : 0;  // the lumped tree has no pieces: broken is one break
            r.impacts.push_back(rec);
            if (rec.speedAfter < lp.stopSpeed) {
                r.reason = StopReason::Rest;
                break;
            }
            continue;
        }
        if (!grounded) continue;
        landed = true;
        ++r.steps;
        v = rebound.apply(v, ground.normal(p.x(), p.y()), rng);
        if (v.norm() < lp.stopSpeed) {
            r.reason = StopReason::Rest;
            break;
        }
        // Leave the surface by a hair so that the next sub-step starts in the air.
        p.z() = std::max(p.z(), ground.height(p.x(), p.y()) + radius + 1e-6);
    }
    record();
    r.cpuSeconds = threadCpuSeconds() - cpu0;
    r.duration = t;
    r.meanDt = r.duration / std::max(1L, r.steps);
    r.meanSpeed = movingTime > 0 ? movingDistance / movingTime : 0;
    r.setStop(p, soil, path);
    return r;
}

}  // namespace sylva::dem
