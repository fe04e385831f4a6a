// The forest's narrow phase (ForestMotion, docs/model.md "The step"): the block's spheres against
// the awake stems, the awake stems against each other (through a pair list kept with a skin) and
// against the soil, each kind kept in its ContactSet. Waking, forces, stepping and sleeping are in
// ForestMotion.cpp.
#include "libdem/ForestMotion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "libdem/ConnectionTouch.hpp"
#include "libdem/SegmentGeometry.hpp"
#include "libdem/SphereContact.hpp"

namespace sylva::dem {

namespace {

// The box around a stem's nodes, widened by its thickest radius (at its foot) and `margin`: every
// connection's surface, and `margin` around it, lies inside.
Eigen::AlignedBox3d widenedNodeBox(const Stem& s, double margin) {
    Eigen::AlignedBox3d box;
    for (const Vec3& p : s.position) box.extend(p);
    const Vec3 widen = Vec3::Constant(0.5 * s.diameterAt(0) + margin);
    return Eigen::AlignedBox3d(box.min() - widen, box.max() + widen);
}

// Whether a point at squared distance `distance2` lies farther than `reach`, told without the root.
// The margin, far above rounding, leaves every case near the bound to the exact tests that follow,
// so that skipping on it changes nothing those tests would decide.
bool beyondReach(double distance2, double reach) { return distance2 > reach * reach * (1 + 1e-9); }

const double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRounding = 1e-9;  // m: far above a surface height's rounding, far below any contact's scale

// History of a contact first seen at this overlap. Stems are checked against each other only
// while awake, so a stem can be woken into a neighbour that already bent into it; the part of the
// overlap no step's motion could explain (kMaxOnsetOverlap) becomes an offset the spring starts from.
constexpr double kMaxOnsetOverlap = 2e-3;  // m: 40 m/s x 5e-5 s, the most one stem step brings
ContactHistory startedAt(double overlap) {
    ContactHistory h;
    h.overlapOffset = std::max(0.0, overlap - kMaxOnsetOverlap);
    return h;
}

// The piece of a broken stem that a contact at t along connection c is on, named by its lowest
// connection (the one above the nearest broken one below c; 0 for the standing stem). A connection
// that has just broken under the contact leaves it with the end it was nearer. A node left alone
// between two breaks, or on top of a broken one, is a piece named by the connection above it (the
// top node: one past the last), which, broken or absent, starts no other piece.
std::uint32_t pieceStart(const Stem& s, std::size_t c, double t) {
    if (s.broken(c) && t >= 0.5) return static_cast<std::uint32_t>(c + 1);
    while (c > 0 && !s.broken(c - 1)) --c;
    return static_cast<std::uint32_t>(c);
}

// What the block touches of connection c: its axis, a0 to a1, and its radius. Broken, c stands for
// node c + 1 when that node is alone (connection c + 1 broken too, or c + 1 the top node): such a node
// keeps its mass, a crown tip of a few kilograms, and meets the block as a sphere, as it meets the
// soil. Its contact is on connection c at t = 1 (nodeOnly: closestOnSegment would put a zero-length
// segment's closest point at t = 0, on node c), so that its force, velocity and step bound are node
// c + 1's. Otherwise nothing.
struct BlockFeature {
    Vec3 a0, a1;
    double radius;
    bool nodeOnly;
};
std::optional<BlockFeature> blockFeature(const Stem& s, std::size_t c) {
    if (!s.broken(c)) return BlockFeature{s.position[c], s.position[c + 1], 0.5 * s.connectionDiameter(c), false};
    if (c + 1 < s.connectionCount() && !s.broken(c + 1)) return std::nullopt;
    return BlockFeature{s.position[c + 1], s.position[c + 1], s.nodeRadius(c + 1), true};
}

}  // namespace

// A point near connection c, at parameter t of its axis: it moves with the axis point
// q = (1 - t) p_c + t p_c+1 and turns with the nodes' interpolated spin about q. Forces are shared
// the same way (applyToConnection), so the contact forces do exactly the work their springs store.
Vec3 ForestMotion::connectionVelocity(const Stem& s, std::size_t c, double t, const Vec3& point) {
    const Vec3 q = (1 - t) * s.position[c] + t * s.position[c + 1];
    const Vec3 spin = (1 - t) * s.angularVelocity[c] + t * s.angularVelocity[c + 1];
    return (1 - t) * s.velocity[c] + t * s.velocity[c + 1] + spin.cross(point - q);
}

// A standing stem starts moving (and sets the step) once the block could reach it within the
// next detections (`approach`), so that their contact begins at the stem's step: at the block's
// own step it would begin centimetres deep.
void ForestMotion::detectBlockStem(const RigidBody& block, const std::vector<Vec3>& centres, double approach) {
    // A connection that broke below a contact, or under it, made a piece of its own: the contact
    // goes on with the piece it is on, its history (tangential spring, dent, onset offset) kept.
    // Begun afresh, it took on at most kMaxOnsetOverlap of its overlap, and the block sank into the
    // falling top.
    blockTouches_.rekey([this](BlockStemTouch& touch, ContactKey key) {
        touch.piece = key[2] = pieceStart(awake(touch.tree)->stem, touch.connection, touch.t);
        return key;
    });
    blockTouches_.beginDetection();
    const Vec3 omega = block.angularVelocity();
    for (auto& a : awake_) {
        const Stem& s = a.stem;
        // No connection of a stem whose nodes' box, widened by its thickest radius, is out of the
        // block's reach can be within it (the test below, connection by connection).
        if (!a.nodeBox) {
            a.nodeBox = widenedNodeBox(s, 0);
            a.nodeBoxSlack = 0;
        }
        if (a.nodeBox->exteriorDistance(block.position) > block.boundingRadius() + approach) continue;
        for (std::size_t c = 0; c < s.connectionCount(); ++c) {
            const std::optional<BlockFeature> feature = blockFeature(s, c);
            if (!feature) continue;
            const Vec3 &a0 = feature->a0, &a1 = feature->a1;
            const double r = feature->radius;
            const auto along = [&](const Vec3& p) { return feature->nodeOnly ? 1.0 : closestOnSegment(p, a0, a1); };
            const double tc = along(block.position);
            if (beyondReach((block.position - (a0 + tc * (a1 - a0))).squaredNorm(), block.boundingRadius() + r + approach))
                continue;
            for (std::uint32_t i = 0; i < centres.size(); ++i) {
                const double rb = block.spheres()[i].radius;
                const double t = along(centres[i]);
                const Vec3 axisPoint = a0 + t * (a1 - a0);
                // Farther than rb + r + approach, the sphere neither touches nor sets the stem moving.
                if (beyondReach((centres[i] - axisPoint).squaredNorm(), rb + r + approach)) continue;
                ContactGeometry found;
                const bool touching = touchSpheres(centres[i], rb, axisPoint, r, found);
                const double overlap = found.overlap;
                if (overlap > -approach) {
                    a.moving = true;
                    a.lastBlockNear = now_;
                }
                if (!touching) continue;
                // One contact per (block sphere, stem piece): the deepest connection; its history
                // moves with it from one connection to the next.
                const std::uint32_t piece = pieceStart(s, c, t);
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
    blockTouches_.sweep([&](BlockStemTouch& t) {
        const Vec3& p = t.geometry.point;
        const Vec3 v = block.velocity + omega.cross(p - block.position) - connectionVelocity(awake(t.tree)->stem, t.connection, t.t, p);
        blockStemLaw_->end(t.geometry, v, t.history, lastDt_, contactLedger_);
    });
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

// Pairs of connections of different awake stems, or of two pieces of a broken one, that may touch:
// within their radii plus the skin of each other when listed. The list holds until some node has
// moved half the skin (then no pair left out can have closed the skin), the awake stems change or a
// connection breaks. A node alone between two breaks meets the block (blockFeature) but not stems:
// as a sphere here it added a fifth to a forested run's CPU (docs/model-stems.md, "… but not yet
// other stems").
void ForestMotion::listStemPairs() {
    stemPairs_.clear();
    // Boxes around each awake stem's nodes, widened by its thickest radius and the skin: most pairs
    // of standing stems are told apart by these alone.
    boxes_.resize(awake_.size());
    for (std::size_t k = 0; k < awake_.size(); ++k) {
        AwakeStem& a = awake_[k];
        a.listedAt = a.stem.position;
        boxes_[k] = widenedNodeBox(a.stem, 0.5 * kStemPairSkin);
    }
    // A connection within reach of the other stem's connection lies, widened by its own radius and half
    // the skin, in the other stem's box: only those are paired (two crossing stems share a few).
    const auto inBox = [](const Stem& s, const Eigen::AlignedBox3d& other, std::vector<std::size_t>& out) {
        out.clear();
        for (std::size_t c = 0; c < s.connectionCount(); ++c) {
            if (s.broken(c)) continue;
            const double r = 0.5 * s.connectionDiameter(c) + 0.5 * kStemPairSkin;
            const Eigen::AlignedBox3d box(s.position[c].cwiseMin(s.position[c + 1]) - Vec3::Constant(r),
                                          s.position[c].cwiseMax(s.position[c + 1]) + Vec3::Constant(r));
            if (box.intersects(other)) out.push_back(c);
        }
    };
    const auto pairIfNear = [this](std::size_t ia, std::size_t ca, std::size_t ib, std::size_t cb) {
        const Stem& A = awake_[ia].stem;
        const Stem& B = awake_[ib].stem;
        const Vec3 &a0 = A.position[ca], &a1 = A.position[ca + 1];
        const Vec3 &b0 = B.position[cb], &b1 = B.position[cb + 1];
        const double near = 0.5 * (A.connectionDiameter(ca) + B.connectionDiameter(cb)) + kStemPairSkin;
        // Cheap rejection on the segments' midpoints before the exact closest points.
        const double reach = near + 0.5 * ((a1 - a0).norm() + (b1 - b0).norm());
        if ((0.5 * (a0 + a1) - 0.5 * (b0 + b1)).squaredNorm() > reach * reach) return;
        const auto [s, t] = closestBetweenSegments(a0, a1, b0, b1);
        if ((a0 + s * (a1 - a0) - b0 - t * (b1 - b0)).squaredNorm() > near * near) return;
        stemPairs_.push_back(ConnectionPair{ia, ib, ca, cb, false});
    };
    for (std::size_t ia = 0; ia < awake_.size(); ++ia)
        for (std::size_t ib = ia + 1; ib < awake_.size(); ++ib) {
            if (!boxes_[ia].intersects(boxes_[ib])) continue;
            inBox(awake_[ia].stem, boxes_[ib], nearA_);
            inBox(awake_[ib].stem, boxes_[ia], nearB_);
            for (const std::size_t ca : nearA_)
                for (const std::size_t cb : nearB_) pairIfNear(ia, ca, ib, cb);
        }
    // The pieces of a broken stem meet one another as they meet other stems: a top breaking off fell
    // through its own stump to the soil.
    for (std::size_t k = 0; k < awake_.size(); ++k) {
        const Stem& s = awake_[k].stem;
        if (!awake_[k].broken) continue;
        for (std::size_t ca = 0; ca < s.connectionCount(); ++ca) {
            if (s.broken(ca)) continue;
            bool apart = false;  // a broken connection between ca and cb: two pieces
            for (std::size_t cb = ca + 1; cb < s.connectionCount(); ++cb) {
                if (s.broken(cb)) {
                    apart = true;
                    continue;
                }
                if (apart) pairIfNear(k, ca, k, cb);
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
        } else {
            pair.checkedStill = false;  // what a check found before either moved no longer holds
        }
        const PlantedStem plantedA{A.stem, trees_.tree(A.tree).foot}, plantedB{B.stem, trees_.tree(B.tree).foot};
        const std::optional<ConnectionTouch> found = touchConnections(plantedA, ca, plantedB, cb);
        if (!found) continue;
        const double s = found->s, t = found->t, overlap = found->geometry.overlap;
        // Stem/stem contacts are frictionless (Table 2: phi_t-t = 0), so they carry no history worth
        // moving along the stems: one contact per pair of connections.
        StemStemTouch* touch = stemTouches_.find(key);
        if (!touch) {
            const bool fused = fusedAtRest(plantedA, ca, plantedB, cb);
            touch = &stemTouches_.add(key, StemStemTouch{A.tree, B.tree, ca, cb, s, t, startedAt(overlap), ContactGeometry{}, false, fused});
        }
        ContactGeometry& g = touch->geometry;
        g = found->geometry;
        g.overlap = std::max(0.0, overlap - touch->history.overlapOffset);
        g.relativeVelocity = connectionVelocity(A.stem, ca, s, g.point) - connectionVelocity(B.stem, cb, t, g.point);
        g.meanSpinNormal = 0.5 * ((1 - s) * A.stem.angularVelocity[ca] + s * A.stem.angularVelocity[ca + 1] +
                                  (1 - t) * B.stem.angularVelocity[cb] + t * B.stem.angularVelocity[cb + 1])
                                     .dot(g.normal);
        touch->s = s;
        touch->t = t;
        touch->touching = true;
    }
    stemTouches_.sweep([&](StemStemTouch& t) {
        const Vec3& p = t.geometry.point;
        const Vec3 v = connectionVelocity(awake(t.treeA)->stem, t.connectionA, t.s, p) -
                       connectionVelocity(awake(t.treeB)->stem, t.connectionB, t.t, p);
        stemStemLaw_->end(t.geometry, v, t.history, lastDt_, contactLedger_);
    });
}

void ForestMotion::detectStemSoil() {
    soilTouches_.beginDetection();
    const double rs = soil_.radius();
    for (auto& touch : soilTouches_)
        if (!awake(touch.tree)->moving) {  // at rest on the soil: as it was, without motion
            touch.touching = true;
            touch.geometry.relativeVelocity.setZero();
            touch.geometry.meanSpinNormal = 0;
        }
    const double rise = soil_.steepestRise();
    for (auto& a : awake_) {
        if (a.soilChecked && !a.moving) continue;
        a.soilChecked = true;
        const Stem& s = a.stem;
        if (a.surfaceSeen.size() != s.nodeCount()) a.surfaceSeen.assign(s.nodeCount(), Vec3::Constant(kNaN));
        for (std::uint32_t k = 1; k < s.nodeCount(); ++k) {
            const Vec3& p = s.position[k];
            const double r = s.nodeRadius(k);
            // Soil tops are at the surface: a node this high above it touches none. The height seen
            // last, raised by the steepest rise over the distance moved since, is as high as the
            // surface under it can be (kRounding: the height's own rounding, a few ulps).
            Vec3& seen = a.surfaceSeen[k];
            const double moved = (p.head<2>() - seen.head<2>()).norm();
            if (p.z() - r > seen.z() + rise * moved + 0.05 + kRounding) continue;  // NaN, never seen: false
            const double surface = soil_.surfaceHeight(p.x(), p.y());
            seen = Vec3(p.x(), p.y(), surface);
            if (p.z() - r > surface + 0.05) continue;
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
    soilTouches_.sweep([&](StemSoilTouch& t) {
        const Stem& s = awake(t.tree)->stem;
        const Vec3 v = s.velocity[t.node] + s.angularVelocity[t.node].cross(t.geometry.point - s.position[t.node]);
        stemSoilLaw_->end(t.geometry, v, t.history, lastDt_, contactLedger_);
    });
}

}  // namespace sylva::dem
