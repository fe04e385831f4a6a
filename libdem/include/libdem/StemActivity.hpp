#pragma once
// When a stem takes part in the run (ForestMotion wakes it, steps it, puts it back to sleep):
// the criteria alone, apart from the bookkeeping that follows them. Sleeping follows motion, as in
// Jolt: a stem joins when the block (or a displaced neighbour) can reach it before the next check,
// and leaves once the block has gone and, if it is broken, its pieces have come to rest.
#include <cstddef>
#include <optional>

#include "libdem/RigidBody.hpp"
#include "libdem/SceneConfig.hpp"
#include "libdem/Stem.hpp"
#include "libdem/StepPhases.hpp"
#include "libdem/TreeField.hpp"

namespace sylva::dem {

class StemActivity {
public:
    explicit StemActivity(const ForestActivity& cfg) : cfg_(cfg) {}

    // How far from its centre the block can touch something before the next detection: its
    // bounding sphere, the margin and its travel until then.
    double blockReach(const RigidBody& block, double travelAhead) const;
    // The block, within `reach` (blockReach), can touch this standing tree: near its base (the
    // widest part) and not flying over its top.
    static bool blockReaches(const RigidBody& block, double reach, const PlacedTree& tree);

    // A node of an awake stem that has left the spot where its tree grew (bent or broken) and may
    // touch a neighbour the block never came near.
    static bool displaced(const Stem& s, std::size_t node, const PlacedTree& own);
    // How far that node can touch before the next neighbour check, `stepsBetweenChecks` steps of
    // dt away: its radius, the margin and twice its travel.
    double nodeReach(const Stem& s, std::size_t node, double dt, int stepsBetweenChecks) const;
    static bool nodeReaches(const Vec3& node, double reach, const PlacedTree& other);

    // What keeps a stem the block touched last at `lastBlockContact` from going back to sleep at t
    // (Waiting: not `sleepAfter` yet; BlockNear: the block within reach of its foot, or able to reach
    // its nodes within the horizon (blockCanReach); PiecesFalling: broken, a piece still moving within
    // `pieceMaxTime`), or nullopt: it may sleep. The stems it touches are the caller's to check (an
    // island sleeps as a whole: ForestMotion::sleep).
    std::optional<StemAwake> holds(const RigidBody& block, const PlacedTree& tree, const Stem& s, bool broken,
                                   double lastBlockContact, double t, double gravity) const;

    // The block could reach this stem within forest.return_horizon_s: its bounding sphere touches the
    // stem's surface at a node or at an intact connection (at the point of its axis closest to the
    // block), or the gap there closes in that time at their speed towards each other along the line
    // between them (the block's velocity, flying on under gravity, less the node's; a connection's
    // point moves with its nodes' velocities weighed by where it lies). No wake margin: the horizon
    // covers what comes next, and a stem the block is about to touch is held by detectBlockStem's
    // approach (ForestMotion::sleep).
    bool blockCanReach(const RigidBody& block, const Stem& s, double gravity) const;
    // A broken (or uprooted) stem whose pieces still move (a node faster than piece_rest_speed_m_s)
    // within piece_max_time_s of the block's last contact: it neither rests nor sleeps, so that a
    // falling top is not frozen mid-air.
    bool piecesFalling(const Stem& s, bool broken, double lastBlockContact, double t) const;
    // A moving stem the block has left may stop where it stands (stay awake, no longer stepped):
    // its pieces are not falling, the block cannot reach it within the horizon, and it has either
    // swung free of the soil and of other stems for sleep_after_s (`lastOtherContact`) or lies still
    // on them (every node slower than piece_rest_speed_m_s). The stems it touches are the caller's
    // (an island rests as a whole).
    bool mayRest(const RigidBody& block, const Stem& s, bool broken, double lastBlockContact, double lastOtherContact,
                 double t, double gravity) const;

private:
    const ForestActivity& cfg_;
};

}  // namespace sylva::dem
