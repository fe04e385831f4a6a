#include "libdem/ForestMotion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "libdem/SegmentGeometry.hpp"
#include "libdem/SphereContact.hpp"

namespace sylva::dem {

namespace {

double potentialEnergy(const Stem& s, double g) {
    double e = 0;
    for (std::size_t i = 0; i < s.nodeCount(); ++i) e += s.mass()[i] * g * s.position[i].z();
    return e;
}

// Broken or uprooted: parts of it fall and are followed until they rest.
bool falling(const Stem& s) { return s.anyConnectionBroken() || s.root().failed(); }

// History of a contact first seen at this overlap. Stems are checked against each other only
// while awake, so a stem can be woken into a neighbour that already bent into it; the part of the
// overlap no step's motion could explain (kMaxOnsetOverlap) becomes an offset the spring starts from.
constexpr double kMaxOnsetOverlap = 2e-3;  // m: 40 m/s x 5e-5 s, the most one stem step brings
ContactHistory startedAt(double overlap) {
    ContactHistory h;
    h.overlapOffset = std::max(0.0, overlap - kMaxOnsetOverlap);
    return h;
}

// Stems of one stool stand so close that their cones meet near the foot: the connections of two
// stems that overlap in the stems' rest shape are one fused stump, not a contact.
bool fusedAtRest(const PlacedTree& a, std::size_t ca, const Stem& sa, const PlacedTree& b, std::size_t cb, const Stem& sb) {
    const double la = sa.connectionLength(), lb = sb.connectionLength();
    const double za0 = a.foot.z() + ca * la, za1 = za0 + la, zb0 = b.foot.z() + cb * lb, zb1 = zb0 + lb;
    constexpr double kSameHeight = 1e-6;  // m: heights are sums of connection lengths, equal up to round-off
    if (za1 < zb0 - kSameHeight || zb1 < za0 - kSameHeight) return false;  // sharing an end height counts
    return (a.foot - b.foot).head<2>().norm() < 0.5 * (sa.connectionDiameter(ca) + sb.connectionDiameter(cb));
}

// What a spring along n at `point` sees of node i: 1/m + |r x n|^2 / I (r from the node's centre).
double nodeInverseMass(const Stem& s, std::size_t i, const Vec3& point, const Vec3& n) {
    double inv = 0;
    if (s.translates(i)) inv += 1 / s.mass()[i];
    if (s.rotates(i)) inv += (point - s.position[i]).cross(n).squaredNorm() / s.inertia()[i];
    return inv;
}

}  // namespace

ForestMotion::ForestMotion(const Scene& scene)
    : cfg_(scene.config()), trees_(scene.trees()), soil_(scene.soil()), activity_(scene.config().activity), stepper_(Vec3(0, 0, -scene.config().gravity)) {
    if (empty()) return;
    blockStemLaw_ = &scene.laws().get(BodyKind::Block, BodyKind::Stem);
    stemStemLaw_ = &scene.laws().get(BodyKind::Stem, BodyKind::Stem);
    stemSoilLaw_ = &scene.laws().get(BodyKind::Stem, BodyKind::Soil);
}

ForestMotion::AwakeStem* ForestMotion::awake(std::uint32_t tree) {
    for (auto& a : awake_)
        if (a.tree == tree) return &a;
    return nullptr;
}

void ForestMotion::wake(std::uint32_t tree, double t) {
    const PlacedTree& p = trees_.tree(tree);
    auto slept = asleep_.find(tree);
    Stem stem = slept != asleep_.end() ? std::move(slept->second) : Stem(p.geometry, cfg_.stem, p.foot, p.support);
    if (slept == asleep_.end()) stem.carryOwnWeight(cfg_.gravity);
    if (slept != asleep_.end()) {
        // Its frozen energy and its ledger go back with it.
        frozenElastic_ -= stem.elasticEnergy();
        frozenPotential_ -= potentialEnergy(stem, cfg_.gravity);
        slept_.addStem(stem.ledger, -1);
        asleep_.erase(slept);
    } else {
        injected_ += potentialEnergy(stem, cfg_.gravity) + stem.elasticEnergy();  // the stem enters the energy budget
    }
    const double step = stem.stableTimeStep();
    const bool broken = falling(stem);
    // The all-awake reference steps every stem, standing or not.
    awake_.push_back(AwakeStem{tree, std::move(stem), {}, step, t, broken, cfg_.activity.allAwake, {}, {}, false, std::nullopt});
    stemPairsStale_ = true;
}

void ForestMotion::detect(const RigidBody& block, const std::vector<Vec3>& centres, double reachAhead, double t,
                          PhaseClock& clock) {
    if (empty()) return;
    now_ = t;
    if (cfg_.activity.allAwake) {
        if (awake_.empty() && asleep_.empty())
            for (std::uint32_t i = 0; i < trees_.size(); ++i) wake(i, t);
    } else {
        // Wake what the block's bounding sphere can reach before the next detection: its travel
        // over the next steps plus a margin, to the stem's surface (the base is the widest part).
        const double reach = activity_.blockReach(block, reachAhead);
        nearTrees_.clear();
        trees_.near(block.position.x(), block.position.y(), reach + 0.75 * trees_.thickest(), nearTrees_);
        for (std::uint32_t i : nearTrees_)
            if (StemActivity::blockReaches(block, reach, trees_.tree(i)) && !awake(i)) wake(i, t);
    }
    wakeNeighbours();
    clock.lap(StepPhase::Wake);
    detectBlockStem(block, centres, reachAhead);
    impacts_.beginStep();
    for (const auto& touch : blockTouches_)
        if (touch.touching) {
            AwakeStem* a = awake(touch.tree);
            a->lastBlockContact = t;
            impacts_.touch(block, touch.tree, trees_.tree(touch.tree), touch.piece, touch.geometry.point, t, a->stem);
        }
    impacts_.endStep(block, [this](std::uint32_t tree) -> const Stem& { return awake(tree)->stem; });
    clock.lap(StepPhase::BlockStem);
    detectStemStem();
    clock.lap(StepPhase::StemStem);
    detectStemSoil();
    setMovingWhereTouched();
    clock.lap(StepPhase::StemSoil);
}

void ForestMotion::setMovingWhereTouched() {
    for (const auto& t : blockTouches_) awake(t.tree)->moving = true;
    for (const auto& t : stemTouches_)
        if (!t.ignored) awake(t.treeA)->moving = awake(t.treeB)->moving = true;
    for (const auto& t : soilTouches_) awake(t.tree)->moving = true;
}

// A point near connection c, at parameter t of its axis: it moves with the axis point
// q = (1 - t) p_c + t p_c+1 and turns with the nodes' interpolated spin about q. Forces are shared
// the same way (applyToConnection), so the contact forces do exactly the work their springs store.
// A bent or broken stem can reach a neighbour the block never came near: wake the stems that
// the displaced nodes of awake stems could touch before the next check. Checked every few steps,
// with the nodes' travel over that time added to the margin.
void ForestMotion::wakeNeighbours() {
    if (++sinceNeighbourCheck_ < kNeighbourCheckInterval) return;
    sinceNeighbourCheck_ = 0;
    toWake_.clear();  // woken after the loop: waking grows awake_, which the loop reads
    for (const AwakeStem& a : awake_) {
        const Stem& s = a.stem;
        const PlacedTree& own = trees_.tree(a.tree);
        for (std::size_t i = 1; i < s.nodeCount(); ++i) {
            if (!StemActivity::displaced(s, i, own)) continue;
            const Vec3& p = s.position[i];
            const double reach = activity_.nodeReach(s, i, lastDt_, kNeighbourCheckInterval);
            nearTrees_.clear();
            trees_.near(p.x(), p.y(), reach + 0.75 * trees_.thickest(), nearTrees_);
            for (std::uint32_t j : nearTrees_)
                if (j != a.tree && !awake(j) && StemActivity::nodeReaches(p, reach, trees_.tree(j))) toWake_.push_back(j);
        }
    }
    std::sort(toWake_.begin(), toWake_.end());
    toWake_.erase(std::unique(toWake_.begin(), toWake_.end()), toWake_.end());
    for (std::uint32_t j : toWake_) wake(j, now_);
}

Vec3 ForestMotion::connectionVelocity(const Stem& s, std::size_t c, double t, const Vec3& point) {
    const Vec3 q = (1 - t) * s.position[c] + t * s.position[c + 1];
    const Vec3 spin = (1 - t) * s.angularVelocity[c] + t * s.angularVelocity[c + 1];
    return (1 - t) * s.velocity[c] + t * s.velocity[c + 1] + spin.cross(point - q);
}

// A standing stem starts moving (and sets the step) once the block could reach it within the
// next detections (`approach`), so that their contact begins at the stem's step: at the block's
// own step it would begin centimetres deep.
void ForestMotion::detectBlockStem(const RigidBody& block, const std::vector<Vec3>& centres, double approach) {
    blockTouches_.beginDetection();
    const Vec3 omega = block.angularVelocity();
    for (auto& a : awake_) {
        const Stem& s = a.stem;
        std::uint32_t piece = 0;  // pieces of a broken stem move apart: each has its own contacts
        for (std::size_t c = 0; c < s.connectionCount(); ++c) {
            if (s.broken(c)) {
                ++piece;
                continue;
            }
            const Vec3& a0 = s.position[c];
            const Vec3& a1 = s.position[c + 1];
            const double r = 0.5 * s.connectionDiameter(c);
            const double tc = closestOnSegment(block.position, a0, a1);
            if ((block.position - (a0 + tc * (a1 - a0))).norm() > block.boundingRadius() + r + approach) continue;
            for (std::uint32_t i = 0; i < centres.size(); ++i) {
                const double rb = block.spheres()[i].radius;
                const double t = closestOnSegment(centres[i], a0, a1);
                ContactGeometry found;
                const bool touching = touchSpheres(centres[i], rb, a0 + t * (a1 - a0), r, found);
                const double overlap = found.overlap;
                if (overlap > -approach) a.moving = true;
                if (!touching) continue;
                // One contact per (block sphere, stem piece): the deepest connection; its history
                // moves with it from one connection to the next.
                const ContactKey key{i, a.tree, piece, 0};
                BlockStemTouch* touch = blockTouches_.find(key);
                if (touch && touch->touching && touch->rawOverlap >= overlap) continue;
                if (!touch)
                    touch = &blockTouches_.add(key, BlockStemTouch{i, a.tree, piece, c, t, overlap, startedAt(overlap), ContactGeometry{}, false, c, overlap});
                ContactGeometry& g = touch->geometry;
                g = found;
                g.overlap = std::max(0.0, overlap - touch->history.overlapOffset);
                g.relativeVelocity = block.velocity + omega.cross(g.point - block.position) - connectionVelocity(s, c, t, g.point);
                g.meanSpinNormal = 0.5 * (omega + (1 - t) * s.angularVelocity[c] + t * s.angularVelocity[c + 1]).dot(g.normal);
                touch->connection = c;
                touch->t = t;
                touch->rawOverlap = overlap;
                touch->touching = true;
            }
        }
    }
    blockTouches_.sweep();
    // A contact that moved to another connection may find it much deeper in the block (a bent or
    // lying stem, a contact that began with an offset): like a new contact, it takes on only the
    // overlap one step's motion can bring, or its spring would store energy no motion loaded.
    for (auto& touch : blockTouches_) {
        if (touch.connection != touch.lastConnection) {
            const double jump = touch.rawOverlap - touch.lastRawOverlap - kMaxOnsetOverlap;
            if (jump > 0) {
                touch.history.overlapOffset += jump;
                touch.geometry.overlap = std::max(0.0, touch.rawOverlap - touch.history.overlapOffset);
            }
        }
        touch.lastConnection = touch.connection;
        touch.lastRawOverlap = touch.rawOverlap;
    }
}

// Pairs of connections of different awake stems that may touch: within their radii plus the skin
// of each other when listed. The list holds until some node has moved half the skin (then no pair
// left out can have closed the skin) or the awake stems change.
void ForestMotion::listStemPairs() {
    stemPairs_.clear();
    // Boxes around each awake stem's nodes, widened by its thickest radius and the skin: most pairs
    // of standing stems are told apart by these alone.
    boxes_.resize(awake_.size());
    for (std::size_t k = 0; k < awake_.size(); ++k) {
        AwakeStem& a = awake_[k];
        a.listedAt = a.stem.position;
        Eigen::AlignedBox3d box;
        for (const Vec3& p : a.stem.position) box.extend(p);
        const double r = 0.5 * a.stem.diameterAt(0) + 0.5 * kStemPairSkin;
        boxes_[k] = Eigen::AlignedBox3d(box.min() - Vec3::Constant(r), box.max() + Vec3::Constant(r));
    }
    for (std::size_t ia = 0; ia < awake_.size(); ++ia)
        for (std::size_t ib = ia + 1; ib < awake_.size(); ++ib) {
            if (!boxes_[ia].intersects(boxes_[ib])) continue;
            const Stem& A = awake_[ia].stem;
            const Stem& B = awake_[ib].stem;
            for (std::size_t ca = 0; ca < A.connectionCount(); ++ca) {
                if (A.broken(ca)) continue;
                const Vec3 &a0 = A.position[ca], &a1 = A.position[ca + 1];
                for (std::size_t cb = 0; cb < B.connectionCount(); ++cb) {
                    if (B.broken(cb)) continue;
                    const Vec3 &b0 = B.position[cb], &b1 = B.position[cb + 1];
                    const double near = 0.5 * (A.connectionDiameter(ca) + B.connectionDiameter(cb)) + kStemPairSkin;
                    // Cheap rejection on the segments' midpoints before the exact closest points.
                    const double reach = near + 0.5 * ((a1 - a0).norm() + (b1 - b0).norm());
                    if ((0.5 * (a0 + a1) - 0.5 * (b0 + b1)).squaredNorm() > reach * reach) continue;
                    const auto [s, t] = closestBetweenSegments(a0, a1, b0, b1);
                    if ((a0 + s * (a1 - a0) - b0 - t * (b1 - b0)).squaredNorm() > near * near) continue;
                    stemPairs_.push_back(ConnectionPair{ia, ib, ca, cb, false});
                }
            }
        }
    stemPairsStale_ = false;
}

bool ForestMotion::stemPairsStale() const {
    if (stemPairsStale_) return true;
    const double limit2 = 0.25 * kStemPairSkin * kStemPairSkin;
    for (const AwakeStem& a : awake_) {
        if (!a.moving) continue;  // never stepped: its nodes are where they were listed
        for (std::size_t i = 0; i < a.stem.nodeCount(); ++i)
            if ((a.stem.position[i] - a.listedAt[i]).squaredNorm() > limit2) return true;
    }
    return false;
}

void ForestMotion::detectStemStem() {
    stemTouches_.beginDetection();
    if (stemPairsStale()) listStemPairs();
    for (ConnectionPair& pair : stemPairs_) {
        const AwakeStem& A = awake_[pair.a];
        const AwakeStem& B = awake_[pair.b];
        const std::size_t ca = pair.connectionA, cb = pair.connectionB;
        const ContactKey key{A.tree, B.tree, static_cast<std::uint32_t>(ca), static_cast<std::uint32_t>(cb)};
        if (!A.moving && !B.moving) {
            // Two stems standing still (a stool's stems fused at their foot): the same contact as at the
            // last check, or none.
            if (pair.checkedStill) {
                if (StemStemTouch* touch = stemTouches_.find(key)) touch->touching = true;
                continue;
            }
            pair.checkedStill = true;
        }
        if (A.stem.broken(ca) || B.stem.broken(cb)) continue;
        const Vec3 &a0 = A.stem.position[ca], &a1 = A.stem.position[ca + 1];
        const Vec3 &b0 = B.stem.position[cb], &b1 = B.stem.position[cb + 1];
        const double ra = 0.5 * A.stem.connectionDiameter(ca), rb = 0.5 * B.stem.connectionDiameter(cb);
        const auto [s, t] = closestBetweenSegments(a0, a1, b0, b1);
        ContactGeometry found;
        if (!touchSpheres(a0 + s * (a1 - a0), ra, b0 + t * (b1 - b0), rb, found)) continue;
        const double overlap = found.overlap;
        // Stem/stem contacts are frictionless (Table 2: phi_t-t = 0), so they carry no history worth
        // moving along the stems: one contact per pair of connections.
        StemStemTouch* touch = stemTouches_.find(key);
        if (!touch) {
            const bool fused = fusedAtRest(trees_.tree(A.tree), ca, A.stem, trees_.tree(B.tree), cb, B.stem);
            touch = &stemTouches_.add(key, StemStemTouch{A.tree, B.tree, ca, cb, s, t, startedAt(overlap), ContactGeometry{}, false, fused});
        }
        ContactGeometry& g = touch->geometry;
        g = found;
        g.overlap = std::max(0.0, overlap - touch->history.overlapOffset);
        g.relativeVelocity = connectionVelocity(A.stem, ca, s, g.point) - connectionVelocity(B.stem, cb, t, g.point);
        g.meanSpinNormal = 0.5 * ((1 - s) * A.stem.angularVelocity[ca] + s * A.stem.angularVelocity[ca + 1] +
                                  (1 - t) * B.stem.angularVelocity[cb] + t * B.stem.angularVelocity[cb + 1])
                                     .dot(g.normal);
        touch->s = s;
        touch->t = t;
        touch->touching = true;
    }
    stemTouches_.sweep();
}

void ForestMotion::detectStemSoil() {
    soilTouches_.beginDetection();
    const double rs = soil_.radius();
    for (auto& a : awake_) {
        if (a.soilChecked && !a.moving) continue;
        a.soilChecked = true;
        const Stem& s = a.stem;
        for (std::uint32_t k = 1; k < s.nodeCount(); ++k) {
            const Vec3& p = s.position[k];
            const double r = 0.5 * s.diameterAt(s.restHeight(k));
            if (p.z() - r > soil_.surfaceHeight(p.x(), p.y()) + 0.05) continue;  // soil tops are at the surface
            nearSoil_.clear();
            soil_.near(p, r + rs, nearSoil_);
            for (std::uint32_t id : nearSoil_) {
                ContactGeometry found;
                if (!touchSpheres(p, r, soil_.center(id), rs, found)) continue;
                const double overlap = found.overlap;
                const ContactKey key{a.tree, k, id, 0};
                StemSoilTouch* touch = soilTouches_.find(key);
                if (!touch) touch = &soilTouches_.add(key, StemSoilTouch{a.tree, k, id, startedAt(overlap), ContactGeometry{}, false});
                ContactGeometry& g = touch->geometry;
                g = found;
                g.overlap = std::max(0.0, overlap - touch->history.overlapOffset);
                g.relativeVelocity = s.velocity[k] + s.angularVelocity[k].cross(g.point - p);
                g.meanSpinNormal = 0.5 * s.angularVelocity[k].dot(g.normal);
                g.movingMass = s.mass()[k];  // the soil sphere does not move
                touch->touching = true;
            }
        }
    }
    soilTouches_.sweep();
}

double ForestMotion::stableStep(const RigidBody& block, StableStep& blockStep) const {
    // Each contact spring k adds k w^2 (1/m + |arm x n|^2 / I) to the squared frequency of each node
    // that carries a share w of it; they add up per node (Gershgorin), and on top of the stem's own
    // springs: omega^2 = (2 / dt_stem)^2 + max over nodes of the contacts' sum.
    for (auto& a : awake_) a.contactOmega2.assign(a.stem.nodeCount(), 0.0);
    auto awakeOf = [this](std::uint32_t tree) -> const AwakeStem& {
        for (const auto& a : awake_)
            if (a.tree == tree) return a;
        throw std::logic_error("contact with a stem that is not awake");
    };
    auto onConnection = [&](std::uint32_t tree, std::size_t c, double t, const ContactGeometry& g, double k) {
        const AwakeStem& a = awakeOf(tree);
        const Vec3 arm = (g.point - ((1 - t) * a.stem.position[c] + t * a.stem.position[c + 1])).cross(g.normal);
        for (const auto& [node, w] : {std::pair<std::size_t, double>{c, 1 - t}, {c + 1, t}}) {
            double inv = 0;
            if (a.stem.translates(node)) inv += 1 / a.stem.mass()[node];
            if (a.stem.rotates(node)) inv += arm.squaredNorm() / a.stem.inertia()[node];
            a.contactOmega2[node] += k * w * w * inv;
        }
    };
    for (const auto& t : blockTouches_) {
        const double k = blockStemLaw_->normalStiffness(t.geometry);
        blockStep.add(k, 0, block.inverseMassAlong(t.geometry.point, t.geometry.normal));
        onConnection(t.tree, t.connection, t.t, t.geometry, k);
    }
    for (const auto& t : stemTouches_) {
        if (t.ignored) continue;
        const double k = stemStemLaw_->normalStiffness(t.geometry);
        onConnection(t.treeA, t.connectionA, t.s, t.geometry, k);
        onConnection(t.treeB, t.connectionB, t.t, t.geometry, k);
    }
    for (const auto& t : soilTouches_) {
        const AwakeStem& a = awakeOf(t.tree);
        a.contactOmega2[t.node] += stemSoilLaw_->normalStiffness(t.geometry) *
                                   nodeInverseMass(a.stem, t.node, t.geometry.point, t.geometry.normal);
    }
    double limit = std::numeric_limits<double>::infinity();
    for (const auto& a : awake_) {
        if (!a.moving) continue;
        const double own = 2 / a.stableStep;
        const double contacts = *std::max_element(a.contactOmega2.begin(), a.contactOmega2.end());
        limit = std::min(limit, 2 / std::sqrt(own * own + contacts));
    }
    return limit;
}

void ForestMotion::applyToConnection(AwakeStem& a, std::size_t c, double t, const Vec3& point, const Vec3& force) {
    // The force's line through the axis point q is carried by the two nodes as (1 - t) and t of it,
    // which also reproduces its moment about any point; what the offset from q to the contact
    // point adds (the friction's moment about the axis, mostly twist) is shared likewise.
    const Vec3& pc = a.stem.position[c];
    const Vec3& pd = a.stem.position[c + 1];
    const Vec3 torque = (point - ((1 - t) * pc + t * pd)).cross(force);
    a.loads.force[c] += (1 - t) * force;
    a.loads.force[c + 1] += t * force;
    a.loads.torque[c] += (1 - t) * torque;
    a.loads.torque[c + 1] += t * torque;
}

void ForestMotion::forces(const RigidBody& block, double dt, Vec3& force, Vec3& torque) {
    if (empty()) return;
    for (auto& a : awake_) {
        a.loads.force.assign(a.stem.nodeCount(), Vec3::Zero());
        a.loads.torque.assign(a.stem.nodeCount(), Vec3::Zero());
    }
    double stored = 0;
    for (auto& t : blockTouches_) {
        const Vec3 f = blockStemLaw_->force(t.geometry, t.history, dt, contactLedger_);  // on the block
        force += f;
        torque += (t.geometry.point - block.position).cross(f);
        applyToConnection(*awake(t.tree), t.connection, t.t, t.geometry.point, -f);
        stored += blockStemLaw_->storedEnergy(t.geometry, t.history);
    }
    for (auto& t : stemTouches_) {
        if (t.ignored) continue;
        const Vec3 f = stemStemLaw_->force(t.geometry, t.history, dt, contactLedger_);  // on stem A
        applyToConnection(*awake(t.treeA), t.connectionA, t.s, t.geometry.point, f);
        applyToConnection(*awake(t.treeB), t.connectionB, t.t, t.geometry.point, -f);
        stored += stemStemLaw_->storedEnergy(t.geometry, t.history);
    }
    for (auto& t : soilTouches_) {
        const Vec3 f = stemSoilLaw_->force(t.geometry, t.history, dt, contactLedger_);
        AwakeStem& a = *awake(t.tree);
        a.loads.force[t.node] += f;
        a.loads.torque[t.node] += (t.geometry.point - a.stem.position[t.node]).cross(f);
        stored += stemSoilLaw_->storedEnergy(t.geometry, t.history);
    }
    budget_ = stored;  // completed by integrate()
}

void ForestMotion::integrate(double dt) {
    if (empty()) return;
    lastDt_ = dt;
    double stems = 0;
    for (auto& a : awake_) {
        if (!a.moving) {
            if (!a.standingBudget) {
                const StemEnergy e = stepper_.energyAtRest(a.stem);
                a.standingBudget = e.total() + e.netLoss + a.stem.ledger.externalWork;  // as below, loads' work excluded
            }
            stems += *a.standingBudget;
            continue;
        }
        const double externalBefore = a.stem.ledger.externalWork;
        const StemEnergy e = stepper_.step(a.stem, dt, a.loads);
        // The stem's own budget without the work of the contact loads, which the contacts' springs
        // and the block account for: energy + dissipated - created, at the step's start.
        stems += e.total() + e.netLoss + 0.5 * (externalBefore + a.stem.ledger.externalWork);
        const bool broken = falling(a.stem);
        if (broken != a.broken) {
            a.stableStep = a.stem.stableTimeStep();  // a broken connection no longer limits the step
            a.broken = broken;
        }
    }
    budget_ += stems + contactLedger_.friction + contactLedger_.contactDamping + contactLedger_.crushing + frozenElastic_ + frozenPotential_ + slept_.frozen + slept_.bendingPlasticity +
               slept_.bendingDamping + slept_.rootPlasticity + slept_.rupture - slept_.unloadingGain - injected_;
}

void ForestMotion::sleep(const RigidBody& block, double t) {
    if (empty() || cfg_.activity.allAwake) return;
    for (std::size_t k = awake_.size(); k-- > 0;) {
        AwakeStem& a = awake_[k];
        if (!activity_.maySleep(block, trees_.tree(a.tree), a.stem, a.broken, a.lastBlockContact, t)) continue;
        bool leaning = false;  // on an awake neighbour
        for (const auto& st : stemTouches_)
            if (!st.ignored && (st.treeA == a.tree || st.treeB == a.tree)) leaning = true;
        if (leaning) continue;
        impacts_.close(a.tree, block, a.stem);
        Stem& s = a.stem;
        // Its vibration stops with it (the block is gone); that energy is booked, not lost silently.
        slept_.frozen += s.kineticEnergy();
        for (std::size_t i = 0; i < s.nodeCount(); ++i) s.velocity[i].setZero(), s.angularVelocity[i].setZero();
        frozenElastic_ += s.elasticEnergy();
        frozenPotential_ += potentialEnergy(s, cfg_.gravity);
        slept_.addStem(s.ledger);
        const std::uint32_t tree = a.tree;
        // Its springs on the soil and on neighbours go with it: their energy is booked as frozen.
        for (const auto& c : soilTouches_)
            if (c.tree == tree) slept_.frozen += stemSoilLaw_->storedEnergy(c.geometry, c.history);
        for (const auto& c : stemTouches_)
            if (!c.ignored && (c.treeA == tree || c.treeB == tree)) slept_.frozen += stemStemLaw_->storedEnergy(c.geometry, c.history);
        soilTouches_.eraseIf([tree](const StemSoilTouch& c) { return c.tree == tree; });
        stemTouches_.eraseIf([tree](const StemStemTouch& c) { return c.treeA == tree || c.treeB == tree; });
        asleep_.emplace(tree, std::move(s));
        awake_.erase(awake_.begin() + static_cast<std::ptrdiff_t>(k));
        stemPairsStale_ = true;
    }
}

std::vector<TreeImpact> ForestMotion::finish(const RigidBody& block) {
    return impacts_.finish(block, [this](std::uint32_t tree) -> const Stem& { return awake(tree)->stem; });
}

ForestLedger ForestMotion::ledger() const {
    ForestLedger l = slept_;
    for (const auto& a : awake_) l.addStem(a.stem.ledger);
    l.contactFriction = contactLedger_.friction;
    l.contactDamping = contactLedger_.contactDamping;
    l.contactCrushing = contactLedger_.crushing;
    return l;
}

}  // namespace sylva::dem
