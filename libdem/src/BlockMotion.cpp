#include "libdem/BlockMotion.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "libdem/ReleaseInsideStem.hpp"
#include "libdem/SimulationError.hpp"
#include "libdem/SphereContact.hpp"
#include "libdem/StableStep.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::dem {

namespace {
// To the centimetre, in plain digits: projected coordinates (925 100 m) read in exponents as 9.251e+05.
std::string where(const Vec3& p) {
    std::ostringstream os;
    os << std::fixed << std::setprecision(2) << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return os.str();
}

// Diameter of a standing stem at `height` above its foot: the cone through the DBH at 1.3 m and
// the tip diameter at H_T (Stem::diameterAt), clamped to the stem.
double standingDiameter(const StemGeometry& g, double tip, double height) {
    const double z = std::clamp(height, 0.0, g.height);
    return tip + (g.dbh - tip) * (g.height - z) / (g.height - 1.3);
}

// K_n holds the block up by overlap: if its weight on one contact would press it deeper than a
// soil sphere's radius, it sinks through the bed and the contacts' geometry loses its meaning
// (soil.kn_n_m = 1 was stopped by the energy audit as a step too large, which it is not).
void refuseSpringTooSoft(const std::string& source, const std::string& key, double kn, double weight, double soilRadius) {
    const double sag = weight / kn;
    if (sag <= soilRadius) return;
    std::ostringstream os;
    os.precision(3);
    os << key << " = " << kn << " N/m: the block's weight (" << weight / 1000 << " kN) on one contact would press it " << sag
       << " m into the soil, more than a soil sphere's radius (" << soilRadius
       << " m), and no contact could hold it up: K_n is in N/m (Table 2: 1e6)";
    throw InputError(source, 0, os.str());
}
}  // namespace

// Every soil the block may land on: the scene's, or each type of a soil map (hazard maps).
void BlockMotion::refuseSoilTooSoft(const Scene& scene) {
    const SceneConfig& cfg = scene.config();
    const double weight = scene.blockTemplate().mass() * cfg.gravity, radius = scene.soil().radius();
    if (const SoilZones* zones = scene.soilZones())
        for (std::size_t k = 0; k < zones->params.size(); ++k)
            refuseSpringTooSoft("", "soil type '" + zones->names[k] + "': kn_n_m", zones->params[k].kn, weight, radius);
    else
        refuseSpringTooSoft(cfg.sourceFile, "soil.kn_n_m", cfg.soilContact.kn, weight, radius);
}

// Like a start inside the soil, a start inside a stem is a bad release, refused up front
// (ReleaseInsideStem.hpp): it stopped such runs at the first step, as "energy grew".
void BlockMotion::refuseStartInsideStem(const Scene& scene) const {
    const TreeField& trees = scene.trees();
    if (trees.size() == 0) return;
    std::vector<std::uint32_t> near;
    // A stem is widest at its foot, whose radius stays under 1.5 DBH for every stem taller than 2 m.
    trees.near(block_.position.x(), block_.position.y(), block_.boundingRadius() + 1.5 * trees.thickest(), near);
    for (std::uint32_t i : near) {
        const PlacedTree& tree = trees.tree(i);
        for (std::size_t k = 0; k < worldCentres_.size(); ++k) {
            const double r = block_.spheres()[k].radius;
            const Vec3& c = worldCentres_[k];
            const double height = c.z() - tree.foot.z();
            if (height - r > tree.geometry.height) continue;  // above the stem's top
            const double stemRadius = 0.5 * standingDiameter(tree.geometry, cfg_.stem.tipDiameter, height);
            if ((c - tree.foot).head<2>().norm() >= r + stemRadius) continue;
            std::ostringstream os;
            os.precision(4);
            os << "the block is released inside stem " << tree.id << " (standing at " << where(tree.foot) << ", DBH "
               << 100 * tree.geometry.dbh << " cm) at " << where(block_.position)
               << ": move the release (release.x_m, release.y_*) or the stem, or lengthen block.launch_distance_m";
            throw ReleaseInsideStem(cfg_.sourceFile, 0, os.str());
        }
    }
}

BlockMotion::BlockMotion(const Scene& scene, const Release& start)
    : cfg_(scene.config()), soil_(scene.soil()), block_(scene.blockTemplate()),
      law_(scene.laws().get(BodyKind::Block, BodyKind::Soil)), forest_(scene) {
    block_.position = start.position;
    block_.orientation = start.orientation;
    block_.velocity = start.velocity;
    worldCentres_.resize(block_.spheres().size());
    updateCentres();
    detectContacts();
    // Below the surface the block may lie under the soil spheres and touch none of them: it would
    // start with no contact and fall for ever.
    const double height = start.position.z() - soil_.surfaceHeight(start.position.x(), start.position.y());
    if (!touches_.empty() || height <= 0) {
        std::ostringstream os;
        os.precision(4);
        os << "the block is released inside the soil at " << where(start.position);
        if (height < 0) os << " (its centre " << -height << " m below the surface)";
        // A block or a terrain changed on --set may have buried it under an unchanged fall height.
        throw cfg_.refusal({"release.fall_height_m", "block.volume_m3", "block.d1_m", "terrain.profile", "terrain.dtm"},
                           os.str() + ": raise release.fall_height_m");
    }
    refuseSoilTooSoft(scene);
    refuseStartInsideStem(scene);
    anticipatedStiffness_ = cfg_.integration.anticipatedContacts * law_.largestNormalStiffness();
    budget_.initialTotal = block_.kineticEnergy() + block_.mass() * cfg_.gravity * block_.position.z();
    lastBlockSide_ = budget_.initialTotal;
}

double BlockMotion::step() {
    PhaseClock clock(phases_, steps_);
    updateCentres();
    detectContacts();
    clock.lap(StepPhase::BlockSoil);
    // how far a block sphere can travel over the next two steps
    const double reach = 2 * (block_.velocity.norm() + block_.angularVelocity().norm() * block_.boundingRadius()) * lastDt_;
    forest_.detect(block_, worldCentres_, reach, t_, clock);
    const double dt = timeStep();
    clock.lap(StepPhase::StableStep);
    Vec3 force(0, 0, -block_.mass() * cfg_.gravity), torque(0, 0, 0);
    double stored = 0;
    for (auto& c : touches_) {
        const Vec3 f = law_.force(c.geometry, c.history, dt, ledger_);
        force += f;
        torque += (c.geometry.point - block_.position).cross(f);
        stored += law_.storedEnergy(c.geometry, c.history);
    }
    forest_.forces(block_, dt, force, torque);
    clock.lap(StepPhase::ContactForces);
    // The stems report their energy at the step's start, which the audit closes with the block's.
    forest_.integrate(dt);
    clock.lap(StepPhase::Stems);
    audit(force, torque, dt, stored, forest_.budgetTerm());
    clock.lap(StepPhase::Audit);
    block_.advance(dt, force, torque);
    t_ += dt;
    ++steps_;
    lastDt_ = dt;
    clock.lap(StepPhase::Block);
    // Stems the block has left, and that have stopped, fall asleep.
    forest_.sleep(block_, t_);
    if (!block_.position.allFinite() || !block_.velocity.allFinite() || !block_.angularMomentum.allFinite())
        throw SimulationError("the block's state became NaN at t = " + std::to_string(t_) + " s (time step " +
                              std::to_string(dt) + " s)");
    if (block_.position.z() < soil_.surfaceHeight(block_.position.x(), block_.position.y()) -
                                  2 * (soil_.radius() + block_.boundingRadius()))
        throw SimulationError("the block fell through the soil at " + where(block_.position) + ", t = " +
                              std::to_string(t_) + " s: contacts too soft or time step too large");
    clock.lap(StepPhase::Sleep);
    return dt;
}

void BlockMotion::updateCentres() {
    for (std::size_t i = 0; i < worldCentres_.size(); ++i) worldCentres_[i] = block_.sphereCentre(i);
}

// Pairs block sphere / soil sphere that overlap now; histories of pairs that stay in touch carry over.
void BlockMotion::detectContacts() {
    touches_.beginDetection();
    candidates_.clear();
    const double rs = soil_.radius();
    soil_.near(block_.position, block_.boundingRadius() + rs, candidates_);
    const Vec3 omega = block_.angularVelocity();
    for (std::uint32_t s : candidates_) {
        const Vec3 cs = soil_.center(s);
        for (std::uint32_t i = 0; i < worldCentres_.size(); ++i) {
            const double rb = block_.spheres()[i].radius;
            ContactGeometry g;
            if (!touchSpheres(worldCentres_[i], rb, cs, rs, g)) continue;
            g.relativeVelocity = block_.velocity + omega.cross(g.point - block_.position);
            g.meanSpinNormal = 0.5 * omega.dot(g.normal);  // the soil does not spin
            const ContactKey key{i, s, 0, 0};
            SoilTouch* touch = touches_.find(key);
            if (!touch) touch = &touches_.add(key, SoilTouch{i, s, ContactHistory{}, ContactGeometry{}, false});
            touch->geometry = g;
            touch->touching = true;
        }
    }
    // Contacts that ended over the last step: the block's velocity over it, where they were.
    touches_.sweep([&](SoilTouch& t) {
        law_.end(t.geometry, block_.velocity + omega.cross(t.geometry.point - block_.position), t.history, lastDt_, ledger_);
    });
}

// The stable step of the springs acting now, plus room for `anticipatedContacts` new soil ones; while
// stems are awake, also theirs (the stiff stem step is paid only then).
double BlockMotion::timeStep() {
    StableStep s;
    const double c = law_.dampingCoefficient();
    s.add(anticipatedStiffness_, c, block_.maxInverseMass());
    for (const auto& tc : touches_)
        s.add(law_.normalStiffness(tc.geometry), c, block_.inverseMassAlong(tc.geometry.point, tc.geometry.normal));
    const double stems = forest_.stableStep(block_, s);
    const double limit = std::min(s.critical(), stems);
    const double forced = cfg_.integration.forcedDt;
    if (forced > 0) {
        if (forced > limit)
            throw SimulationError("integration.dt_s = " + std::to_string(forced) + " s is above the stable limit " +
                                  std::to_string(limit) + " s of the contacts active at t = " + std::to_string(t_) +
                                  " s; use a smaller step or 0 (automatic)");
        return forced;
    }
    // The block's own bound, at its default safety 0.3 (omega dt <= 0.6), cannot resonate as StepHold describes.
    return std::min(cfg_.integration.safety * s.critical(), stemStep_.next(cfg_.integration.stemSafety * stems));
}

// Audited at t, where positions and contact springs are: the leapfrog's velocities are half a step
// off, so they are first synchronised with half of this step's forces. Energy appearing from
// nowhere means the integration went wrong.
void BlockMotion::audit(const Vec3& force, const Vec3& torque, double dt, double soilStored, double forestTerm) {
    const double m = block_.mass();
    const Vec3 v = block_.velocity + 0.5 * dt * force / m;
    const Vec3 w = (block_.orientation.conjugate() * (block_.angularMomentum + 0.5 * dt * torque))
                       .cwiseQuotient(block_.principalInertia());
    budget_.kinetic = 0.5 * m * v.squaredNorm() + 0.5 * w.dot(block_.principalInertia().cwiseProduct(w));
    budget_.potential = m * cfg_.gravity * block_.position.z();
    budget_.stored = soilStored + forestTerm;
    budget_.contactDamping = ledger_.contactDamping;
    budget_.friction = ledger_.friction;
    const double blockSide = budget_.kinetic + budget_.potential + soilStored + ledger_.contactDamping + ledger_.friction;
    const double total = blockSide + forestTerm;
    // Energy converted so far: what left the potential, and at least the release's kinetic energy
    // plus the fall to the ground.
    const double scale = std::max(budget_.initialTotal - budget_.potential,
                                  budget_.initialTotal - m * cfg_.gravity * (block_.position.z() - cfg_.release.fallHeight));
    const double rel = (total - budget_.initialTotal) / scale;
    budget_.imbalance = std::max(budget_.imbalance, std::abs(rel));
    budget_.flagged = budget_.imbalance > cfg_.integration.energyWarning;
    const double blockRise = blockSide - lastBlockSide_, forestRise = forestTerm - lastForestTerm_;
    lastBlockSide_ = blockSide;
    lastForestTerm_ = forestTerm;
    if (!(rel > cfg_.integration.energyTolerance)) return;
    // Say where the last step's energy appeared: the remedies differ.
    std::ostringstream os;
    os.precision(3);
    os << "energy grew without a source at t = " << t_ << " s (+" << 100 * rel << " % of the energy converted; "
       << "in the last step the block, soil and their contacts gained " << blockRise << " J, the stems and their "
       << "contacts " << forestRise << " J): ";
    if (forestRise > blockRise)
        os << "a stem's step is too large, or a connection between two of its nodes turned too far; lower "
              "integration.stem_safety or refine stem.node_spacing_m";
    else
        os << "the time step is too large for these contact parameters; lower integration.safety or integration.dt_s";
    throw SimulationError(os.str());
}

double BlockMotion::clearance() const {
    // Only the spheres' heights: the rotation's last row against each offset, not each centre turned.
    const Vec3 up = block_.orientation.toRotationMatrix().row(2).transpose();
    double lowest = std::numeric_limits<double>::infinity();
    for (const ClumpSphere& s : block_.spheres()) lowest = std::min(lowest, up.dot(s.offset) - s.radius);
    lowest += block_.position.z();
    return std::max(0.0, lowest - soil_.surfaceHeight(block_.position.x(), block_.position.y()));
}

}  // namespace sylva::dem
