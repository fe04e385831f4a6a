// The forest's part of a block run: waking stems, their contacts' forces, stepping the moving
// ones, putting them back to sleep, and the energy they carry in and out (ForestMotion.hpp). Finding
// the contacts is ForestContacts.cpp.
#include "libdem/ForestMotion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace sylva::dem {

namespace {

double potentialEnergy(const Stem& s, double g) {
    double e = 0;
    for (std::size_t i = 0; i < s.nodeCount(); ++i) e += s.mass()[i] * g * s.position[i].z();
    return e;
}

// Broken or uprooted: parts of it fall and are followed until they rest.
bool falling(const Stem& s) { return s.anyConnectionBroken() || s.root().failed(); }

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

// Looked up by hash, as the contacts are: every contact asks for its stems at every step.
const ForestMotion::AwakeStem* ForestMotion::awake(std::uint32_t tree) const {
    const auto slot = awakeSlot_.find(tree);
    return slot == awakeSlot_.end() ? nullptr : &awake_[slot->second];
}

ForestMotion::AwakeStem* ForestMotion::awake(std::uint32_t tree) {
    return const_cast<AwakeStem*>(std::as_const(*this).awake(tree));
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
    const StableStep stability = stem.stability();
    const bool broken = falling(stem);
    // The all-awake reference steps every stem, standing or not.
    awakeSlot_[tree] = awake_.size();
    awake_.emplace_back(tree, std::move(stem), stability, t, broken, cfg_.activity.allAwake);
    awake_.back().breaksSeen = awake_.back().stem.breakCount();
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

// The block sets what it touches moving, and a moving stem what it touches; the soil, and a stem at
// rest, do not: a stem resting on them stays at rest (sleeping bodies in contact, as in Jolt).
void ForestMotion::setMovingWhereTouched() {
    for (auto& a : awake_) a.onSoilOrStem = false;
    for (const auto& t : blockTouches_) awake(t.tree)->moving = true;
    for (const auto& t : stemTouches_)
        if (!t.ignored) {
            AwakeStem *a = awake(t.treeA), *b = awake(t.treeB);
            if (a->moving || b->moving) a->moving = b->moving = true;
            a->onSoilOrStem = b->onSoilOrStem = true;
        }
    for (const auto& t : soilTouches_) awake(t.tree)->onSoilOrStem = true;
    for (auto& a : awake_)
        if (a.onSoilOrStem) a.lastOtherContact = now_;
}

// A bent or broken stem can reach a neighbour the block never came near: wake the stems that
// the displaced nodes of moving stems could touch before the next check. Checked every few steps,
// with the nodes' travel over that time added to the margin. Each pair found is kept until the next
// check: the stem reached may not sleep while the moving one stays awake (sleep).
void ForestMotion::wakeNeighbours() {
    if (++sinceNeighbourCheck_ < kNeighbourCheckInterval) return;
    sinceNeighbourCheck_ = 0;
    neighbourReach_.clear();  // woken after the loop: waking grows awake_, which the loop reads
    for (const AwakeStem& a : awake_) {
        // A stem at rest reaches nothing it did not reach when it stopped; woken by it, a sleeping
        // neighbour would stand awake for sleep_after_s, fall asleep and be woken again.
        if (!a.moving) continue;
        const Stem& s = a.stem;
        const PlacedTree& own = trees_.tree(a.tree);
        for (std::size_t i = 1; i < s.nodeCount(); ++i) {
            if (!StemActivity::displaced(s, i, own)) continue;
            const Vec3& p = s.position[i];
            const double reach = activity_.nodeReach(s, i, lastDt_, kNeighbourCheckInterval);
            nearTrees_.clear();
            trees_.near(p.x(), p.y(), reach + 0.75 * trees_.thickest(), nearTrees_);
            for (std::uint32_t j : nearTrees_)
                if (j != a.tree && StemActivity::nodeReaches(p, reach, trees_.tree(j))) neighbourReach_.push_back({a.tree, j});
        }
    }
    const auto order = [](const NeighbourReach& x, const NeighbourReach& y) {
        return std::tie(x.reached, x.moving) < std::tie(y.reached, y.moving);
    };
    const auto same = [](const NeighbourReach& x, const NeighbourReach& y) { return x.reached == y.reached && x.moving == y.moving; };
    std::sort(neighbourReach_.begin(), neighbourReach_.end(), order);  // woken in tree order, whatever found them
    neighbourReach_.erase(std::unique(neighbourReach_.begin(), neighbourReach_.end(), same), neighbourReach_.end());
    for (const NeighbourReach& r : neighbourReach_)
        if (!awake(r.reached)) wake(r.reached, now_);
}

double ForestMotion::stableStep(const RigidBody& block, StableStep& blockStep) const {
    // A contact spring k along n vibrates on its own (a rank-one stiffness) at omega^2 = k W, W the
    // inverse mass of everything it pushes apart along n: the block's, and each stem node's share
    // w^2 (1/m + |arm x n|^2 / I) of a connection it touches; its dashpot c damps it at the rate c W.
    // Each node it moves takes both, they add up per node over its contacts, and on top of the stem's
    // own bound: omega^2 and the damping rate, which the soil's dashpot (Eq. 16, a ratio of 0.54)
    // makes as much a limit as the springs.
    for (auto& a : awake_) a.contactBounds.assign(a.stem.nodeCount(), StableStep{});
    auto awakeOf = [this](std::uint32_t tree) -> const AwakeStem& {
        if (const AwakeStem* a = awake(tree)) return *a;
        throw std::logic_error("contact with a stem that is not awake");
    };
    struct Share {
        const AwakeStem* stem;
        std::size_t node;
    };
    std::array<Share, 4> moved{};
    std::size_t count = 0;
    double inverse = 0;
    auto onConnection = [&](std::uint32_t tree, std::size_t c, double t, const ContactGeometry& g) {
        const AwakeStem& a = awakeOf(tree);
        const Vec3 arm = (g.point - ((1 - t) * a.stem.position[c] + t * a.stem.position[c + 1])).cross(g.normal);
        for (const auto& [node, w] : {std::pair<std::size_t, double>{c, 1 - t}, {c + 1, t}}) {
            double inv = 0;
            if (a.stem.translates(node)) inv += 1 / a.stem.mass()[node];
            if (a.stem.rotates(node)) inv += arm.squaredNorm() / a.stem.inertia()[node];
            inverse += w * w * inv;
            if (w * w * inv > 0) moved[count++] = Share{&a, node};
        }
    };
    auto book = [&](double k, double c) {
        for (std::size_t m = 0; m < count; ++m) moved[m].stem->contactBounds[moved[m].node].add(k, c, inverse);
        count = 0;
        inverse = 0;
    };
    for (const auto& t : blockTouches_) {
        const double k = blockStemLaw_->normalStiffness(t.geometry), c = blockStemLaw_->dampingCoefficientAt(t.geometry);
        const double blockInverse = block.inverseMassAlong(t.geometry.point, t.geometry.normal);
        blockStep.add(k, c, blockInverse);  // the block's own side, at its own safety
        onConnection(t.tree, t.connection, t.t, t.geometry);
        inverse += blockInverse;
        book(k, c);
    }
    for (const auto& t : stemTouches_) {
        if (t.ignored) continue;
        onConnection(t.treeA, t.connectionA, t.s, t.geometry);
        onConnection(t.treeB, t.connectionB, t.t, t.geometry);
        book(stemStemLaw_->normalStiffness(t.geometry), stemStemLaw_->dampingCoefficientAt(t.geometry));
    }
    for (const auto& t : soilTouches_) {
        const AwakeStem& a = awakeOf(t.tree);
        a.contactBounds[t.node].add(stemSoilLaw_->normalStiffness(t.geometry), stemSoilLaw_->dampingCoefficientAt(t.geometry),
                                    nodeInverseMass(a.stem, t.node, t.geometry.point, t.geometry.normal));
    }
    double limit = std::numeric_limits<double>::infinity();
    for (const auto& a : awake_) {
        if (!a.moving) continue;
        limit = std::min(limit, a.stability.critical());
        for (const StableStep& node : a.contactBounds) {
            if (node.omegaSquared() == 0) continue;  // no contact: the stem's own bound, taken above
            StableStep both = a.stability;
            both += node;
            limit = std::min(limit, both.critical());
        }
    }
    return limit;
}

void ForestMotion::applyToConnection(AwakeStem& a, std::size_t c, double t, const Vec3& point, const Vec3& force) {
    if (!a.moving) return;  // a stem at rest that a moving one touches: not stepped this step
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
    // A stem at rest is not stepped: its loads are not read, and its contacts with the soil and with
    // other resting stems hold still, without work or dissipation, so they only keep their springs'
    // energy.
    for (auto& a : awake_) {
        if (!a.moving) continue;
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
        if (!awake(t.treeA)->moving && !awake(t.treeB)->moving) {
            stored += stemStemLaw_->storedEnergy(t.geometry, t.history);
            continue;
        }
        const Vec3 f = stemStemLaw_->force(t.geometry, t.history, dt, contactLedger_);  // on stem A
        applyToConnection(*awake(t.treeA), t.connectionA, t.s, t.geometry.point, f);
        applyToConnection(*awake(t.treeB), t.connectionB, t.t, t.geometry.point, -f);
        stored += stemStemLaw_->storedEnergy(t.geometry, t.history);
    }
    for (auto& t : soilTouches_) {
        AwakeStem& a = *awake(t.tree);
        if (!a.moving) {
            stored += stemSoilLaw_->storedEnergy(t.geometry, t.history);
            continue;
        }
        const Vec3 f = stemSoilLaw_->force(t.geometry, t.history, dt, contactLedger_);
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
        // lastBlockContact is set to the step's time at each touch: equal, the block touches it now.
        nodeSteps_[a.lastBlockContact == now_ ? StemAwake::Touched : a.heldBy] += a.stem.nodeCount();
        if (a.broken) nodeSteps_.broken += a.stem.nodeCount();
        if (a.onSoilOrStem) nodeSteps_.onSoilOrStem += a.stem.nodeCount();
        const double externalBefore = a.stem.ledger.externalWork;
        const StemEnergy e = stepper_.step(a.stem, dt, a.loads, a.stepped ? StemStart::Moving : StemStart::FromRest);
        a.stepped = true;
        a.nodeBoxSlack += e.farthestMove;
        if (a.nodeBox && a.nodeBoxSlack <= kNodeBoxSlack) {
            const Vec3 widen = Vec3::Constant(e.farthestMove);
            a.nodeBox = Eigen::AlignedBox3d(a.nodeBox->min() - widen, a.nodeBox->max() + widen);
        } else {
            a.nodeBox.reset();
        }
        // The stem's own budget without the work of the contact loads, which the contacts' springs
        // and the block account for: energy + dissipated - created, at the step's start.
        stems += e.total() + e.netLoss + 0.5 * (externalBefore + a.stem.ledger.externalWork);
        const bool broken = falling(a.stem);
        if (broken != a.broken || a.stem.breakCount() != a.breaksSeen) {
            a.stability = a.stem.stability();  // a broken connection no longer limits the step
            a.broken = broken;
            // A new break makes new pieces, and pairs of them that may touch (listStemPairs).
            if (a.stem.breakCount() != a.breaksSeen) stemPairsStale_ = true;
            const long id = trees_.tree(a.tree).id;
            for (std::size_t k = a.breaksSeen; k < a.stem.breakCount(); ++k) {
                const std::uint32_t c = a.stem.breakOrder()[k];
                breaks_.push_back({id, now_, a.stem.connectionHeight(c), a.stem.connectionDiameter(c)});
            }
            a.breaksSeen = a.stem.breakCount();
        }
    }
    budget_ += stems + contactLedger_.friction + contactLedger_.contactDamping + contactLedger_.crushing + frozenElastic_ + frozenPotential_ + slept_.frozen + slept_.bendingPlasticity +
               slept_.bendingDamping + slept_.axialDamping + slept_.rootPlasticity + slept_.rupture - slept_.unloadingGain - injected_;
}

// Stems that touch one another form an island (Islands.hpp): its moving stems rest together, and it
// sleeps as a whole. Stem by stem, a stem touching a moving neighbour could not rest, nor one touching
// any awake neighbour sleep: two broken stems rolling down the slope against each other, or leaning
// on each other, were stepped to the end of the run (docs/performance.md, "Islands").
void ForestMotion::sleep(const RigidBody& block, double t) {
    if (empty() || cfg_.activity.allAwake) return;
    const std::size_t n = awake_.size();
    islands_.reset(n);
    const auto index = [this](std::uint32_t tree) { return awakeSlot_.at(tree); };
    for (const auto& c : stemTouches_)
        if (!c.ignored) islands_.join(index(c.treeA), index(c.treeB));  // ignored: fused at rest, no force

    // Rest: no moving stem of the island is touched by the block now or within the approach that sets
    // a stem moving (detectBlockStem: rested, it would be set moving again at the next step, and so
    // on), and each may rest (StemActivity::mayRest, the costlier test, asked only while its island
    // still may).
    islands_.allowAll();
    for (std::size_t i = 0; i < n; ++i)
        if (awake_[i].moving && (awake_[i].lastBlockContact == now_ || awake_[i].lastBlockNear == now_)) islands_.forbid(i);
    for (std::size_t i = 0; i < n; ++i) {
        const AwakeStem& a = awake_[i];
        if (a.moving && islands_.allowed(i) &&
            !activity_.mayRest(block, a.stem, a.broken, a.lastBlockContact, a.lastOtherContact, t, cfg_.gravity))
            islands_.forbid(i);
    }
    for (std::size_t i = 0; i < n; ++i)
        if (awake_[i].moving && islands_.allowed(i)) rest(awake_[i]);

    // Sleep: nothing holds any stem of the island (StemActivity::holds); the others lean on the held ones.
    // A stem a moving neighbour could reach at the last check sleeps with that neighbour: asleep
    // before it, it would be woken again by the next check; kept awake for it whatever, two stems
    // swaying within reach of each other (a stool's) held each other to the end of the run.
    reachedByNeighbour_.assign(n, false);
    for (const NeighbourReach& r : neighbourReach_) {
        const auto from = awakeSlot_.find(r.moving), to = awakeSlot_.find(r.reached);
        if (from == awakeSlot_.end() || to == awakeSlot_.end()) continue;
        islands_.join(from->second, to->second);
        reachedByNeighbour_[to->second] = true;
    }
    islands_.allowAll();
    held_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const AwakeStem& a = awake_[i];
        // One the block came within a step's approach of holds as one it may reach (rest, above).
        if (a.lastBlockNear == now_)
            held_[i] = StemAwake::BlockNear;
        else
            held_[i] = activity_.holds(block, trees_.tree(a.tree), a.stem, a.broken, a.lastBlockContact, t, cfg_.gravity);
        if (held_[i]) islands_.forbid(i);
    }
    for (std::size_t k = n; k-- > 0;) {
        AwakeStem& a = awake_[k];
        if (!islands_.allowed(k)) {
            a.heldBy = held_[k] ? *held_[k] : reachedByNeighbour_[k] ? StemAwake::NeighbourNear : StemAwake::Leaning;
            continue;
        }
        impacts_.close(a.tree, block, a.stem);
        rest(a);  // its vibration stops with it (the block is gone): booked, not lost silently
        Stem& s = a.stem;
        frozenElastic_ += s.elasticEnergy();
        frozenPotential_ += potentialEnergy(s, cfg_.gravity);
        slept_.addStem(s.ledger);
        const std::uint32_t tree = a.tree;
        // Its springs on the soil and on neighbours go with it: their energy is booked as frozen.
        for (const auto& c : soilTouches_)
            if (c.tree == tree) slept_.frozen += stemSoilLaw_->storedEnergy(c.geometry, c.history);
        for (const auto& c : stemTouches_)
            if (!c.ignored && (c.treeA == tree || c.treeB == tree)) slept_.frozen += stemStemLaw_->storedEnergy(c.geometry, c.history);
        // The block's too, left from its last touch when the wait (forest.sleep_after_s) is shorter
        // than a step: the next detection would find their stem gone.
        for (const auto& c : blockTouches_)
            if (c.tree == tree) slept_.frozen += blockStemLaw_->storedEnergy(c.geometry, c.history);
        blockTouches_.eraseIf([tree](const BlockStemTouch& c) { return c.tree == tree; });
        soilTouches_.eraseIf([tree](const StemSoilTouch& c) { return c.tree == tree; });
        stemTouches_.eraseIf([tree](const StemStemTouch& c) { return c.treeA == tree || c.treeB == tree; });
        asleep_.emplace(tree, std::move(s));
        awake_.erase(awake_.begin() + static_cast<std::ptrdiff_t>(k));
        awakeSlot_.erase(tree);
        for (std::size_t j = k; j < awake_.size(); ++j) awakeSlot_[awake_[j].tree] = j;  // moved down by one
        stemPairsStale_ = true;
    }
}

// The stem stops where it stands, awake: its contacts stay, and the block, or a moving stem, sets it
// moving again from rest. What it still moved with is booked as left vibrating.
void ForestMotion::rest(AwakeStem& a) {
    Stem& s = a.stem;
    const double kinetic = s.kineticEnergy();
    slept_.frozen += kinetic;
    if (falling(s)) slept_.frozenPieces += kinetic;
    for (std::size_t i = 0; i < s.nodeCount(); ++i) s.velocity[i].setZero(), s.angularVelocity[i].setZero();
    a.moving = false;
    a.stepped = false;
    a.standingBudget.reset();
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
