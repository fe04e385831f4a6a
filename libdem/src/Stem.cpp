#include "libdem/Stem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Eigenvalues>

#include "libdem/RotationVector.hpp"
#include "libdem/StableStep.hpp"
#include "libstand/Allometry.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::dem {

namespace {

const double kPi = std::acos(-1.0);
constexpr double kBreastHeight = 1.3;  // m, where the DBH is measured
// A connection folded (or twisted) this far has broken whatever Fig. 3 says: long, thin connections
// reach M_Rupt only after turning more than pi (the rotation needed grows with l / D_con), where
// the rotation vector would wrap round and the hinge's state lose its meaning.
const double kFoldedConnection = kPi / 2;

void validate(const StemGeometry& g, const StemParams& p) {
    const auto fail = [](const std::string& what) { throw InputError("stem geometry: " + what); };
    if (!(g.dbh > 0) || !std::isfinite(g.dbh)) fail("DBH " + std::to_string(g.dbh) + " m must be > 0");
    if (!(g.height > kBreastHeight) || !std::isfinite(g.height))
        fail("height " + std::to_string(g.height) + " m must exceed the breast height 1.3 m");
    if (!(g.crownLength >= 0 && g.crownLength <= g.height))
        fail("crown length " + std::to_string(g.crownLength) + " m must be in [0, height]");
    if (!(g.crownMass >= 0) || !std::isfinite(g.crownMass))
        fail("crown mass " + std::to_string(g.crownMass) + " kg must be >= 0");
    if (p.tipDiameter > g.dbh)
        fail("tip diameter " + std::to_string(p.tipDiameter) + " m exceeds the DBH " + std::to_string(g.dbh) + " m");
}

}  // namespace

StemGeometry beechStem(double dbhCm) {
    if (!(dbhCm > 0) || !std::isfinite(dbhCm)) throw InputError("stem DBH " + std::to_string(dbhCm) + " cm must be > 0");
    StemGeometry g;
    g.dbh = dbhCm / 100;
    g.height = stand::treeHeightM(dbhCm);            // Eq. 11
    g.crownLength = stand::crownLengthM(g.height);   // Eq. 12
    g.crownMass = stand::crownMassKg(dbhCm);         // Eq. 13
    return g;
}

std::vector<double> Stem::connectionLengths(const StemGeometry& g, const StemParams& p, std::size_t* footCount) {
    const auto cut = [](double span, double spacing, std::vector<double>& lengths) {
        const std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(span / spacing - 1e-9)));
        lengths.insert(lengths.end(), n, span / n);
    };
    const double height = g.height;
    std::vector<double> lengths;
    const double foot = std::min(p.footZone, height);
    if (foot > 0) cut(foot, 0.5 * p.nodeSpacing, lengths);
    const std::size_t inFoot = lengths.size();
    if (footCount) *footCount = inFoot;
    if (height <= foot) return lengths;
    // A bole the block's push whips breaks up to its crown base (a 20 cm stem, 13.9 m high, at 7-8 m
    // against a base at 8.2 m): cut coarser there, the break's place and its release move by a whole
    // connection.
    const double crownBase = height - g.crownLength;
    const double zone = p.upperSpacingFactor > 1 ? std::min(std::max({p.struckZone, crownBase, foot}), height) : height;
    if (zone > foot) cut(zone - foot, p.nodeSpacing, lengths);
    if (height > zone) {
        const double lower = lengths.back();
        cut(height - zone, p.upperSpacingFactor * p.nodeSpacing, lengths);
        // Connections above the zone shorter than below it would shorten the step for nothing: a stem
        // barely taller than the zone is cut at the node spacing all the way up.
        if (lengths.back() < lower) {
            lengths.resize(inFoot);
            cut(height - foot, p.nodeSpacing, lengths);
        }
    }
    return lengths;
}

double Stem::diameterAt(double z) const {
    // Linear taper through the DBH at 1.3 m to the tip diameter at H_T.
    const double tip = params_.tipDiameter;
    return tip + (geometry_.dbh - tip) * (geometry_.height - z) / (geometry_.height - kBreastHeight);
}

Stem::Stem(const StemGeometry& g, const StemParams& p, const Vec3& foot, StemFoot support)
    : geometry_(g), params_(p), support_(support), footRest_(Quat::Identity()), root_(p.root, p.bending.reading) {
    sylva::dem::validate(p);
    validate(g, p);
    std::size_t footCount = 0;
    const std::vector<double> length = connectionLengths(g, p, &footCount);
    const std::size_t n = length.size();
    // The foot zone's connections, l_f long against l_c above it, would shorten the explicit step by
    // l_f / l_c: the axial and shear elements' frequencies go as 1 / l. Their axial and shear springs
    // softened and their nodes' rotational inertia raised by (l_c / l_f)^2 keep each element's
    // frequency where the coarse ones' is (docs/model-stems.md, "The foot zone").
    // Never below 1: a coarse part thinner than the zone's connections (a graded stem's sliver above
    // it) is not a reason to stiffen the zone.
    const double footScale = footCount > 0 && footCount < n ? std::max(1.0, std::pow(length[footCount] / length[0], 2)) : 1.0;
    // Connection c's springs; node i's rotational inertia, the zone's top node included: lightened by
    // the zone's short connection below it, it would let the coarse connection above it set the step.
    const auto scaledSpring = [&](std::size_t c) { return c < footCount ? footScale : 1.0; };
    const auto scaledTurn = [&](std::size_t i) { return i <= footCount ? footScale : 1.0; };
    const auto frustumMass = [&](double l, double da, double db) { return p.density * kPi * l * (da * da + da * db + db * db) / 12; };
    restHeight_.assign(1, 0);
    for (std::size_t c = 0, first = 0; c < n; ++c) {
        if (length[c] != length[first]) first = c;  // the next zone (above the foot zone, or the graded stem's upper one) begins
        restHeight_.push_back(restHeight_[first] + static_cast<double>(c + 1 - first) * length[c]);
    }

    position.resize(n + 1);
    velocity.assign(n + 1, Vec3::Zero());
    angularVelocity.assign(n + 1, Vec3::Zero());
    orientation.assign(n + 1, Quat::Identity());
    mass_.assign(n + 1, 0.0);
    inertia_.assign(n + 1, 0.0);
    std::vector<double> diameter(n + 1);
    for (std::size_t i = 0; i <= n; ++i) {
        position[i] = foot + Vec3(0, 0, restHeight(i));
        diameter[i] = diameterAt(restHeight(i));
    }

    const double shearModulus = p.bending.moe / (2 * (1 + p.poisson));
    for (std::size_t c = 0; c < n; ++c) {
        const double da = diameter[c], db = diameter[c + 1], l = length[c];
        // The cone's segment (a frustum), half on each node.
        const double segmentMass = frustumMass(l, da, db);
        mass_[c] += 0.5 * segmentMass;
        mass_[c + 1] += 0.5 * segmentMass;

        const double dCon = 0.5 * (da + db);  // mean diameter between the nodes
        const double area = kPi * dCon * dCon / 4;
        const double polar = kPi * std::pow(dCon, 4) / 32;
        ConnectionBeam beam(p.bending, da, db, shearModulus * area / l / scaledSpring(c), l, p.bending.sections);
        const BendingDamping damping(p.bending, beam.coefficients());
        connections_.push_back(Connection{l, dCon, p.bending.moe * area / l / p.axialSoftening / scaledSpring(c),
                                          shearModulus * polar / l, std::move(beam), damping});
        if (p.bending.fractureEnergy > 0)
            connections_.back().fracture = ConnectionFracture(p.bending.fractureEnergy, dCon);
    }

    if (p.root.anchorage == RootAnchorage::StemWeight) {
        // Winching tests: the critical turning moment grows with the stem's fresh mass (Nicoll et al.
        // 2006); the root keeps the rotation at which it yields, M_a / K_Root, of the given parameters.
        double stemMass = 0;
        for (const double m : mass_) stemMass += m;  // the cone alone: the crown is added below
        RootSpringParams anchored = p.root;
        anchored.yieldMoment = p.root.turningMomentPerKg * stemMass;
        anchored.stiffness = p.root.stiffness * anchored.yieldMoment / p.root.yieldMoment;
        root_ = RootSpring(anchored, p.bending.reading);
    }

    // Crown: m_C spread over the nodes within L_C of the top (the top node at least), each node
    // carrying the crown along the connection below it (the foot, the one above): on equal
    // connections, equally over the nodes, as the paper spreads it.
    // (In units of the top connection, so that equal connections give exactly equal shares.)
    const auto inCrown = [&](std::size_t i) { return g.height - restHeight(i) <= g.crownLength + 1e-9 * g.height; };
    const auto carried = [&](std::size_t i) { return length[i == 0 ? 0 : i - 1] / length.back(); };
    double crownSpan = 0;
    for (std::size_t i = 0; i <= n; ++i) crownSpan += inCrown(i) ? carried(i) : 0;
    for (std::size_t i = 0; i <= n; ++i)
        if (inCrown(i)) mass_[i] += g.crownMass / crownSpan * carried(i);

    // A share of the stem L long about its centre.
    const auto lumped = [](double m, double d, double share) { return m * (d * d / 16 + share * share / 12); };
    for (std::size_t i = 0; i <= n; ++i) {
        const double share = 0.5 * ((i == 0 ? 0 : length[i - 1]) + (i == n ? 0 : length[i]));
        inertia_[i] = lumped(mass_[i], diameter[i], share) * scaledTurn(i);
    }
    // The root spring is not softened with the zone, and a thin stem's foot inertia is set by its share
    // of the stem, l_f / 2 against l_c / 2: scaled as the zone is, it would still turn faster on the
    // root than the coarse stem's foot, and the root's element would set the step. Floor it there.
    if (footScale > 1) {
        const double lc = length[footCount], d0 = diameter[0];
        inertia_[0] = std::max(inertia_[0], lumped(0.5 * frustumMass(lc, d0, diameterAt(lc)), d0, lc / 2));
    }
    for (std::size_t i = 0; i <= n; ++i) {
        inverseMass_.push_back(1 / mass_[i]);
        inverseInertia_.push_back(1 / inertia_[i]);
    }
    // Wood's loss factor damps its axial vibration as it damps its bending (docs/model-stems.md,
    // "Time step"): a dashpot c = eta k / omega, omega the connection's highest axial frequency
    // (omega^2 = k (1/m_a + 1/m_b), each node's mass halved between its two connections, the top's
    // whole: a nominal frequency that sets c once; stability() splits the masses by the wood, which
    // differs from it by the taper on a uniform stem), gives the loss factor eta there and less below.
    // The paper's stem has none.
    if (p.bending.damping == StemDamping::ConstantLoss)
        for (std::size_t c = 0; c < n; ++c) {
            const auto share = [&](std::size_t i) { return translates(i) ? (i == n ? 1.0 : 2.0) / mass_[i] : 0.0; };
            Connection& k = connections_[c];
            k.axialDamping = p.bending.lossFactor * std::sqrt(k.axial / (share(c) + share(c + 1)));
        }
}

void Stem::carryOwnWeight(double gravity) {
    double weightAbove = 0, stored = 0;
    for (std::size_t c = connections_.size(); c-- > 0;) {
        weightAbove += mass_[c + 1] * gravity;
        Connection& k = connections_[c];
        k.weightCompression = weightAbove / k.axial;
        stored += 0.5 * weightAbove * k.weightCompression;
    }
    elasticEnergy_ = stored;
}

void Stem::updateConnections(std::vector<Vec3>& force, std::vector<Vec3>& torque, double dt) {
    const BendingDamping::Decay decay = BendingDamping::decayOver(dt);
    double stored = 0;
    for (std::size_t c = 0; c < connections_.size(); ++c) {
        Connection& k = connections_[c];
        if (k.bending.broken()) continue;
        const std::size_t a = c, b = c + 1;
        // Relative rotation of b with respect to a. Its components are the same in a's frame, b's
        // frame and the frame halfway between them, which is the connection's frame.
        const Quat relative = orientation[a].conjugate() * orientation[b];
        const Vec3 theta = rotationVector(relative);
        // As a matrix: it turns four vectors, each a matrix product where a quaternion's costs twice that.
        const Eigen::Matrix3d frame = (orientation[a] * halfway(relative)).toRotationMatrix();
        const Vec3 chord = frame.transpose() * (position[b] - position[a]);  // in the connection frame
        const Vec3 stretch = chord - Vec3(0, 0, k.length + k.weightCompression);  // shear x, y; axial z
        // The axial dashpot's work over the step just made, booked now that its stretch is known:
        // its force times the stretch it resisted (exact, as the laws' work is; the rate the force
        // was given lags half a step, which near the stable limit makes c v^2 dt overstate it).
        ledger.axialDamping += k.dashpotForce * (stretch.z() - k.dashpotStretch);
        k.dashpotStretch = stretch.z();

        const HingeWork w = theta.squaredNorm() > kFoldedConnection * kFoldedConnection ? k.bending.snap()
                                                             : k.bending.deform(theta.head<2>(), stretch.head<2>());
        // Once a connection with a fracture energy has reached M_Rupt it transmits (1 - d) of what its
        // intact bending and shear would (ConnectionFracture); its hinge's plastic work is then the
        // fracture's. Without one, d stays 0 and the products below are exact.
        const double kept = k.fracture.carried();
        (k.fracture.started() ? ledger.rupture : ledger.bendingPlasticity) += kept * w.dissipated;
        ledger.unloadingGain += kept * w.created;
        const double linear = 0.5 * (k.axial * stretch.z() * stretch.z() + k.twist * theta.z() * theta.z());
        if (k.bending.broken()) {
            // M_Rupt reached (Eq. 6, brittle) or folded: resistance lost along all axes
            ledger.rupture += kept * w.released + linear + kept * k.damping.release();
            breakOrder_.push_back(static_cast<std::uint32_t>(c));
            continue;
        }

        // theta moves at J^-1 R_a^T (omega_b - omega_a), J^-1 = inverseLeftJacobian(theta); the moment M
        // conjugate to theta acts on a as R_a J^-T M and on b as the opposite, so its power is exactly
        // -M . dtheta/dt. With R_a = R_frame R(theta / 2)^T both go through the connection's frame and
        // the symmetric S = J^-1 R(theta / 2) (midpointInverseJacobian): rate S R_frame^T (omega_b -
        // omega_a), moment R_frame S M on a.
        const RotationJacobian toTheta = midpointInverseJacobian(theta);
        const Vec3 rate = toTheta * (frame.transpose() * (angularVelocity[b] - angularVelocity[a]));
        const BendingDamping::Step damped = k.damping.advance(rate.head<2>(), decay);
        ledger.bendingDamping += kept * damped.dissipated;
        if (k.bending.ruptureReached()) {
            const double intact = k.bending.storedEnergy() + k.damping.storedEnergy();  // psi0
            ledger.rupture += k.fracture.advance(w.dissipated, stretch.head<2>(), intact);
            if (k.fracture.through()) {
                // advance has released what the bending and its damping stored: their returns are not booked again
                k.bending.snap();
                k.damping.release();
                ledger.rupture += linear;
                breakOrder_.push_back(static_cast<std::uint32_t>(c));
                continue;
            }
            stored += k.fracture.carried() * intact + linear;
        } else {
            // Two sums, in this order: merged, they move the last bits of the runs without a fracture energy.
            stored += linear + k.bending.storedEnergy();
            stored += k.damping.storedEnergy();
        }
        const double carried = k.fracture.carried();  // after this step's damage, as the forces below are
        const Vec2& damping = damped.moment;

        const Vec2& mb = k.bending.moment();
        const Vec3 moment(carried * (mb.x() + damping.x()), carried * (mb.y() + damping.y()), k.twist * theta.z());
        // The axial and shear springs pull the nodes apart along the chord (f on a, -f on b) and,
        // through their frame halfway between a and b, turn it: chord x f in all, shared by the nodes as
        // the frame follows them (exactly half each for small theta). Node b's share is
        // (1/2) R_a J^-T J_r(theta / 2)^T R_frame^T (chord x f), and R_frame^T (chord x f) is the cross
        // product of the two in the connection frame; b's share and the moment act through the same
        // R_a J^-T = R_frame S, so they are summed before it.
        const Vec2 shear = k.bending.shearForce();
        // Wood's internal friction in the axial spring: a dashpot along it, at the nodes' mid-step velocities.
        k.dashpotForce = k.axialDamping * (velocity[b] - velocity[a]).dot(frame.col(2));
        const Vec3 springs(carried * shear.x(), carried * shear.y(), k.axial * stretch.z() + k.dashpotForce);
        const Vec3 turn = chord.cross(springs);
        const Vec3 couple =
            frame * toTheta.transposeTimes(moment - 0.5 * rightJacobian(0.5 * theta).transposeTimes(turn));
        const Vec3 f = frame * springs;
        force[a] += f;
        force[b] -= f;
        torque[a] += frame * turn + couple;
        torque[b] -= couple;
    }
    if (support_ == StemFoot::RootSpring) {
        Vec3 theta = rotationVector(footRest_.conjugate() * orientation[0]);
        // A foot turned past pi (an uprooted tree rolling over): follow it the long way round, as the
        // incremental root law needs, rather than jump to the short way.
        const double angle = theta.norm();
        if (angle > 0 && (theta - rootAngle_).norm() > kPi) theta -= 2 * kPi / angle * theta;
        ledger.rootPlasticity += root_.rotate(theta - rootAngle_);  // Eqs. 9-10
        rootAngle_ = theta;
        torque[0] -= footRest_ * inverseLeftJacobian(theta).transposeTimes(root_.moment());
        stored += root_.storedEnergy();
    }
    elasticEnergy_ = stored;
}

double Stem::lowestBreakHeight() const {
    for (std::size_t c = 0; c < connections_.size(); ++c)
        if (connections_[c].bending.broken()) return connectionHeight(c);
    return std::nan("");
}

double Stem::kineticEnergy() const {
    double e = 0;
    for (std::size_t i = 0; i < nodeCount(); ++i)
        e += 0.5 * (mass_[i] * velocity[i].squaredNorm() + inertia_[i] * angularVelocity[i].squaredNorm());
    return e;
}

// The element eigenvalue inequality (Irons 1970; Hughes 1987, "The Finite Element Method", Sect. 9.3,
// "Estimation of the maximum eigenvalue"): with every node's mass shared out among the elements that
// hold it, the highest frequency of the assembled chain lies below the highest of any element on its
// own. Each connection's elements decouple, at any orientation (their eigenvalues do not depend on
// it): the axial spring, the twist spring, and in each plane the beam's bending and shear acting on
// two translations and two rotations. The axial element is exact for a uniform chain (4 k / m), and
// it is the stem's highest mode (the axial wave, dt = l sqrt(rho / MOE)): the bound is within a few
// per cent of the eigenvalues of the whole stem (StemTimeStep), where summing the spring kinds node by
// node (Gershgorin) gave the step away 1.7 times. Yielding and breaking only soften the springs.
double Stem::stableTimeStep() const { return stability().critical(); }

StableStep Stem::stability() const {
    const std::size_t n = nodeCount();
    // The bound holds for any split of a node's mass and inertia among the elements that hold it: its
    // unbroken connections. Split in proportion to the wood each brings (l D_con^2), which is half and
    // half on a uniform stem up to the taper, and at the top of a foot zone hands the coarse connection
    // its own half segment (2/3 of the node), not half of a node lightened by the zone's shorter one.
    // The root spring is one element with the first connection while that holds (a partition of the
    // stiffness like any other), alone after.
    const auto wood = [&](std::size_t c) { return connections_[c].length * connections_[c].diameter * connections_[c].diameter; };
    std::vector<double> held(n, 0.0);
    for (std::size_t c = 0; c < connections_.size(); ++c)
        if (!connections_[c].bending.broken()) held[c] += wood(c), held[c + 1] += wood(c);
    double omega2 = 0, gamma = 0;  // the elements' largest
    for (std::size_t c = 0; c < connections_.size(); ++c) {
        const Connection& k = connections_[c];
        if (k.bending.broken()) continue;
        const std::size_t a = c, b = c + 1;
        // This element's share of node i's mass and inertia is wood(c) / held[i] of them.
        const auto invMass = [&](std::size_t i) { return translates(i) ? held[i] / wood(c) / mass_[i] : 0.0; };
        const auto invInertia = [&](std::size_t i) { return rotates(i) ? held[i] / wood(c) / inertia_[i] : 0.0; };
        const double ma = invMass(a), mb = invMass(b), ia = invInertia(a), ib = invInertia(b);
        // One plane: (u_a, phi_a, u_b, phi_b) -> theta = phi_b - phi_a and eps = (2 / l) (u_b - u_a) + phi_a + phi_b
        // (ConnectionBeam's generalised deformations of a straight connection), up to signs that do not
        // change the eigenvalues.
        Eigen::Matrix<double, 2, 4> strain;
        strain << 0, -1, 0, 1, -2 / k.length, 1, 2 / k.length, 1;
        Eigen::Matrix2d s = k.bending.elasticStiffness();
        s(0, 0) += k.damping.addedStiffness();
        Eigen::Matrix4d stiffness = strain.transpose() * s * strain;
        if (c == 0 && support_ == StemFoot::RootSpring) stiffness(1, 1) += root_.stiffness();
        const Eigen::Vector4d scale = Eigen::Vector4d(ma, ia, mb, ib).cwiseSqrt();
        const Eigen::Matrix4d normalised = scale.asDiagonal() * stiffness * scale.asDiagonal();
        const double plane = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(normalised, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
        omega2 = std::max({omega2, plane, k.axial * (ma + mb), k.twist * (ia + ib)});
        // The bending dashpot acts on theta, the axial one along the connection.
        gamma = std::max({gamma, k.damping.viscosity() * (ia + ib), k.axialDamping * (ma + mb)});
    }
    if (support_ == StemFoot::RootSpring && held[0] == 0) omega2 = std::max(omega2, root_.stiffness() / inertia_[0]);
    // The fastest mode and the most damped one need not be the same: both bounds enter together.
    StableStep bound;
    bound.add(omega2, gamma, 1);
    return bound;
}

}  // namespace sylva::dem
