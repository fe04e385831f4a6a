#include "libdem/BlockRun.hpp"

#include <gsl/gsl_rng.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include "libdem/SimulationError.hpp"
#include "libdem/StableStep.hpp"
#include "libstand/InputError.hpp"

namespace sylva::dem {

std::string toString(StopReason r) {
    switch (r) {
        case StopReason::Rest: return "rest";
        case StopReason::LeftDomain: return "left_domain";
        case StopReason::TimeLimit: return "time_limit";
    }
    return "?";
}

namespace {

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

struct Rng {
    explicit Rng(std::uint64_t seed) : r(gsl_rng_alloc(gsl_rng_mt19937)) { gsl_rng_set(r, static_cast<unsigned long>(seed)); }
    ~Rng() { gsl_rng_free(r); }
    Rng(const Rng&) = delete;
    Rng& operator=(const Rng&) = delete;
    double uniform(double a, double b) { return a + (b - a) * gsl_rng_uniform(r); }
    gsl_rng* r;
};

// A block sphere touching a soil sphere, with the history its law carries between steps.
struct SoilTouch {
    std::uint32_t blockSphere;
    std::uint32_t soilSphere;
    ContactHistory history;
    ContactGeometry geometry;
    bool touching;
};

std::string where(const Vec3& p) {
    std::ostringstream os;
    os.precision(4);
    os << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return os.str();
}

class BlockSimulation {
public:
    BlockSimulation(const Scene& scene, std::uint64_t seed)
        : cfg_(scene.config()), soil_(scene.soil()), block_(scene.blockTemplate()),
          law_(scene.laws().get(BodyKind::Block, BodyKind::Soil)) {
        const Release rel = drawRelease(scene, seed);
        block_.position = rel.position;
        block_.orientation = rel.orientation;
        release_ = block_.position;
        worldCentres_.resize(block_.spheres().size());
        updateCentres();
        detectContacts();
        if (!touches_.empty())
            throw InputError(cfg_.sourceFile, 0, "the block is released inside the soil at " + where(release_) +
                                                     ": raise release.fall_height_m");
        anticipatedStiffness_ = cfg_.integration.anticipatedContacts * law_.normalStiffness(ContactGeometry{});
    }

    RunResult run(const RunOptions& options) {
        RunResult r;
        r.release = release_;
        const double g = cfg_.gravity;
        const double m = block_.mass();
        budget_.initialTotal = block_.kineticEnergy() + m * g * block_.position.z();
        double restTimer = 0, nextSample = 0, movingTime = 0, movingDistance = 0;
        bool landed = false;
        double t = 0;
        const double cpu0 = threadCpuSeconds();
        for (;;) {
            if (options.recordTrajectory && t >= nextSample) {
                r.trajectory.push_back(sample(t));
                nextSample += cfg_.trajectoryInterval;
            }
            // detect contacts -> time step -> forces -> integrate
            updateCentres();
            detectContacts();
            const double dt = timeStep(t);
            Vec3 force(0, 0, -m * g), torque(0, 0, 0);
            double stored = 0;
            for (auto& c : touches_) {
                const Vec3 f = law_.force(c.geometry, c.history, dt, ledger_);
                force += f;
                torque += (c.geometry.point - block_.position).cross(f);
                stored += law_.storedEnergy(c.geometry, c.history);
            }
            audit(force, torque, dt, stored, t);
            block_.advance(dt, force, torque);
            t += dt;
            ++r.steps;

            if (!block_.position.allFinite() || !block_.velocity.allFinite())
                throw SimulationError("the block's state became NaN at t = " +
                                      std::to_string(t) + " s (time step " + std::to_string(dt) + " s)");

            const double speed = block_.velocity.norm();
            r.maxSpeed = std::max(r.maxSpeed, speed);
            landed = landed || !touches_.empty();
            if (landed) r.maxBounce = std::max(r.maxBounce, clearance());
            const bool resting = speed < cfg_.stop.restSpeed &&
                                 block_.angularVelocity().norm() * block_.boundingRadius() < cfg_.stop.restSpeed;
            if (landed && !resting) {
                movingTime += dt;
                movingDistance += speed * dt;
            }
            restTimer = resting ? restTimer + dt : 0;
            const auto reason = stopReason(restTimer, t);
            if (reason) {
                r.reason = *reason;
                break;
            }
        }
        r.cpuSeconds = threadCpuSeconds() - cpu0;
        if (options.recordTrajectory) r.trajectory.push_back(sample(t));
        r.duration = t;
        r.meanDt = t / std::max(1L, r.steps);
        r.stop = block_.position;
        r.meanSpeed = movingTime > 0 ? movingDistance / movingTime : 0;
        r.runoutAlongSlope = soil_.alongSlope(release_.x(), r.stop.x(), r.stop.y());
        r.runoutHorizontal = (r.stop - release_).head<2>().norm();
        r.energyLineDeg = r.runoutHorizontal > 0 ? std::atan2(release_.z() - r.stop.z(), r.runoutHorizontal) * 180 / M_PI : 0;
        budget_.kinetic = block_.kineticEnergy();
        budget_.potential = m * g * block_.position.z();
        budget_.contactDamping = ledger_.contactDamping;
        budget_.friction = ledger_.friction;
        r.energy = budget_;
        return r;
    }

private:
    void updateCentres() {
        for (std::size_t i = 0; i < worldCentres_.size(); ++i) worldCentres_[i] = block_.sphereCentre(i);
    }

    // Pairs block sphere / soil sphere that overlap now; histories of pairs that stay in touch carry over.
    void detectContacts() {
        for (auto& c : touches_) c.touching = false;
        candidates_.clear();
        const double rs = soil_.radius();
        soil_.near(block_.position, block_.boundingRadius() + rs, candidates_);
        const Vec3 omega = block_.angularVelocity();
        for (std::uint32_t s : candidates_) {
            const Vec3 cs = soil_.center(s);
            for (std::uint32_t i = 0; i < worldCentres_.size(); ++i) {
                const double rb = block_.spheres()[i].radius;
                const Vec3 d = worldCentres_[i] - cs;
                const double dist2 = d.squaredNorm();
                if (dist2 >= (rb + rs) * (rb + rs)) continue;
                const double dist = std::sqrt(dist2);
                ContactGeometry g;
                g.normal = d / dist;
                g.overlap = rb + rs - dist;
                g.point = cs + g.normal * (rs - 0.5 * g.overlap);
                g.relativeVelocity = block_.velocity + omega.cross(g.point - block_.position);
                g.meanSpinNormal = 0.5 * omega.dot(g.normal);
                g.radiusA = rb;
                g.radiusB = rs;
                touch(i, s).geometry = g;
            }
        }
        touches_.erase(std::remove_if(touches_.begin(), touches_.end(), [](const SoilTouch& c) { return !c.touching; }),
                       touches_.end());
    }

    SoilTouch& touch(std::uint32_t blockSphere, std::uint32_t soilSphere) {
        for (auto& c : touches_)
            if (c.blockSphere == blockSphere && c.soilSphere == soilSphere) {
                c.touching = true;
                return c;
            }
        touches_.push_back(SoilTouch{blockSphere, soilSphere, ContactHistory{}, ContactGeometry{}, true});
        return touches_.back();
    }

    // The stable step of the springs acting now, plus room for `anticipatedContacts` new ones.
    double timeStep(double t) const {
        StableStep s;
        const double c = law_.dampingCoefficient();
        s.add(anticipatedStiffness_, c, block_.maxInverseMass());
        for (const auto& tc : touches_)
            s.add(law_.normalStiffness(tc.geometry), c, block_.inverseMassAlong(tc.geometry.point, tc.geometry.normal));
        const double limit = s.critical();
        const double forced = cfg_.integration.forcedDt;
        if (forced > 0) {
            if (forced > limit)
                throw SimulationError("integration.dt_s = " + std::to_string(forced) + " s is above the stable limit " +
                                      std::to_string(limit) + " s of the contacts active at t = " + std::to_string(t) +
                                      " s; use a smaller step or 0 (automatic)");
            return forced;
        }
        return cfg_.integration.safety * limit;
    }

    // The budget must close; energy appearing from nowhere means the integration went wrong.
    // Audited at t, where positions and contact springs are: the leapfrog's velocities are half a
    // step off, so they are synchronised with half of this step's forces first.
    void audit(const Vec3& force, const Vec3& torque, double dt, double stored, double t) {
        const double m = block_.mass();
        const Vec3 v = block_.velocity + 0.5 * dt * force / m;
        const Vec3 w = (block_.orientation.conjugate() * (block_.angularMomentum + 0.5 * dt * torque))
                           .cwiseQuotient(block_.principalInertia());
        const double kinetic = 0.5 * m * v.squaredNorm() + 0.5 * w.dot(block_.principalInertia().cwiseProduct(w));
        const double potential = m * cfg_.gravity * block_.position.z();
        const double dissipated = ledger_.contactDamping + ledger_.friction;
        const double total = kinetic + potential + stored + dissipated;
        // Energy converted so far: what left the potential; at least the release's fall energy.
        const double scale = std::max(budget_.initialTotal - potential, m * cfg_.gravity * cfg_.release.fallHeight);
        const double rel = (total - budget_.initialTotal) / scale;
        budget_.imbalance = std::max(budget_.imbalance, std::abs(rel));
        budget_.stored = stored;
        if (rel > cfg_.integration.energyTolerance)
            throw SimulationError("energy grew without a source at t = " + std::to_string(t) + " s (+" +
                                  std::to_string(100 * rel) + " % of the energy converted): the time step is too large "
                                  "for these contact parameters; lower integration.safety or integration.dt_s");
    }

    double clearance() const {
        double lowest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < worldCentres_.size(); ++i)
            lowest = std::min(lowest, worldCentres_[i].z() - block_.spheres()[i].radius);
        return std::max(0.0, lowest - soil_.surfaceHeight(block_.position.x(), block_.position.y()));
    }

    std::optional<StopReason> stopReason(double restTimer, double t) const {
        const Vec3& p = block_.position;
        if (p.x() < soil_.xmin() || p.x() > soil_.xmax() || p.y() < soil_.ymin() || p.y() > soil_.ymax())
            return StopReason::LeftDomain;
        if (p.z() < soil_.surfaceHeight(p.x(), p.y()) - 2 * (soil_.radius() + block_.boundingRadius()))
            throw SimulationError("the block fell through the soil at " + where(p) + ", t = " + std::to_string(t) +
                                  " s: contacts too soft or time step too large");
        if (restTimer >= cfg_.stop.restTime) return StopReason::Rest;
        if (t >= cfg_.stop.maxTime) return StopReason::TimeLimit;
        return std::nullopt;
    }

    TrajectorySample sample(double t) const {
        const Vec3 w = block_.angularVelocity();
        const double et = 0.5 * block_.mass() * block_.velocity.squaredNorm();
        return {t, block_.position, block_.velocity, w, et, block_.kineticEnergy() - et};
    }

    const SceneConfig& cfg_;
    const SoilBed& soil_;
    RigidBody block_;
    const ContactLaw& law_;
    Vec3 release_;
    std::vector<Vec3> worldCentres_;
    std::vector<std::uint32_t> candidates_;
    std::vector<SoilTouch> touches_;
    double anticipatedStiffness_ = 0;
    DissipationLedger ledger_;
    EnergyBudget budget_;
};

}  // namespace

Release drawRelease(const Scene& scene, std::uint64_t seed) {
    Rng rng(seed);
    const auto& cfg = scene.config();
    const auto& rel = cfg.release;
    Quat q = Quat::Identity();
    if (rel.randomOrientation) {
        const double ax = rng.uniform(0, M_PI), ay = rng.uniform(0, M_PI), az = rng.uniform(0, M_PI);
        q = Eigen::AngleAxisd(az, Vec3::UnitZ()) * Eigen::AngleAxisd(ay, Vec3::UnitY()) * Eigen::AngleAxisd(ax, Vec3::UnitX());
    }
    const double y = rel.yMax > rel.yMin ? rng.uniform(rel.yMin, rel.yMax) : rel.yMin;
    const SoilBed& soil = scene.soil();
    if (rel.x < soil.xmin() || rel.x > soil.xmax() || y < soil.ymin() || y > soil.ymax())
        throw InputError(cfg.sourceFile, 0, "release point (" + std::to_string(rel.x) + ", " + std::to_string(y) +
                                                ") is outside the terrain");
    return {Vec3(rel.x, y, soil.surfaceHeight(rel.x, y) + rel.fallHeight), q};
}

RunResult simulateBlock(const Scene& scene, int run, std::uint64_t seed, const RunOptions& options) {
    BlockSimulation sim(scene, seed);
    RunResult r = sim.run(options);
    r.run = run;
    r.seed = seed;
    return r;
}

}  // namespace sylva::dem
