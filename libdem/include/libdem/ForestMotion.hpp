#pragma once
// The forest's part of a block run. Stems are plain data (TreeField) until the block comes near:
// then a stem is built into the simulation (woken), integrated while the block can touch it, and
// put back to sleep once the block has left it (its deformed or broken shape is kept). A woken
// stem stands in static equilibrium (Stem::carryOwnWeight) and is only stepped once something
// touches it: the stiff stem time step is paid only while stems move. A moving stem the block cannot
// reach any more stops where it stands (rests), awake and in its contacts, until the block or a
// moving stem touches it again; stems touching one another rest and sleep together (Islands). When a
// stem wakes, rests and may sleep is StemActivity's; what waking, resting and sleeping do to the
// run's energy and contacts is here.
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "libdem/BlockRun.hpp"
#include "libdem/ContactSet.hpp"
#include "libdem/ForestLedger.hpp"
#include "libdem/ImpactRecorder.hpp"
#include "libdem/Islands.hpp"
#include "libdem/StableStep.hpp"
#include "libdem/StemActivity.hpp"
#include "libdem/StemStepper.hpp"
#include "libdem/StepPhases.hpp"

namespace sylva::dem {


class ForestMotion {
public:
    explicit ForestMotion(const Scene& scene);

    bool empty() const { return trees_.size() == 0; }
    std::size_t awakeCount() const { return awake_.size(); }

    // Wakes the stems the block is about to reach, then finds the block/stem, stem/stem and
    // stem/soil contacts (histories carried, also when a contact slides along a stem).
    void detect(const RigidBody& block, const std::vector<Vec3>& blockCentres, double reachAhead, double t,
                PhaseClock& clock);
    // The largest stable step of the awake stems and their contacts (infinity if none); the block's
    // side of the block/stem springs is added to `blockStep`.
    double stableStep(const RigidBody& block, StableStep& blockStep) const;
    // Contact forces for a step dt: the block's share is added to force and torque (about its centre).
    void forces(const RigidBody& block, double dt, Vec3& force, Vec3& torque);
    // Advances the awake stems by dt (connections, root springs, gravity, contact loads).
    void integrate(double dt);
    // Rests the moving stems the block cannot reach within forest.return_horizon_s; puts to sleep
    // the stems the block has left, closing their impact records; stems in contact do either together.
    void sleep(const RigidBody& block, double t);
    // Closes every open impact record and returns all of them, in the order they began.
    std::vector<TreeImpact> finish(const RigidBody& block);

    // Energy of the forest at the last integrate(): stems' kinetic + elastic + potential, springs
    // of the forest's contacts, plus what left it (ledger); minus the potential energy the stems
    // had when they were woken (they enter the budget then).
    double budgetTerm() const { return budget_; }
    const NodeSteps& nodeSteps() const { return nodeSteps_; }
    // The stem of tree `tree` as it is now, if awake (null if asleep or never woken).
    const Stem* awakeStem(std::uint32_t tree) const {
        const AwakeStem* a = awake(tree);
        return a ? &a->stem : nullptr;
    }
    ForestLedger ledger() const;
    const std::vector<StemBreak>& breaks() const { return breaks_; }  // so far, in the order they broke

private:
    struct AwakeStem {
        // Woken at `wokenAt`, standing still unless `moving` (the all-awake reference steps it at once).
        AwakeStem(std::uint32_t tree, Stem stem, const StableStep& stability, double wokenAt, bool broken, bool moving)
            : tree(tree), stem(std::move(stem)), stability(stability), lastBlockContact(wokenAt), broken(broken),
              moving(moving) {}
        std::uint32_t tree;
        Stem stem;
        StemLoads loads;
        StableStep stability;  // its own springs' (Stem::stability)
        double lastBlockContact;  // time of the last block contact (or of waking)
        bool broken;              // some connection broken or the root plate gone: its pieces fall
        std::size_t breaksSeen = 0;  // its broken connections when its stability and the stem pairs were last made
        bool moving;              // stepped: set by a touch of the block or of a moving stem, cleared
                                  // when it rests; until then it stands still, is not stepped and
                                  // does not limit the time step
        StemAwake heldBy = StemAwake::Waiting;  // what kept it awake at the last sleep check, once the block left it
        mutable std::vector<StableStep> contactBounds;  // per node, from the contacts' springs and dashpots (stableStep)
        std::vector<Vec3> listedAt;  // node positions when stemPairs_ was made
        // Checked against the soil since woken. A stem that does not move keeps its nodes where they
        // were checked, and its contacts with the soil as they were: it needs no new check.
        bool soilChecked = false;
        bool onSoilOrStem = false;  // touching the soil or another stem at the last detection
        double lastOtherContact = -std::numeric_limits<double>::infinity();  // time of the last detection that found it so
        // Its energy and its ledger's balance while it stands still: the same at every step until it moves.
        std::optional<double> standingBudget;
        // The box around its nodes the block is first tested against (detectBlockStem), kept while it
        // is not stepped (most awake stems stand, waiting for the block, and their nodes do not move)
        // and, while it is, widened by each step's farthest node move until that adds up to
        // kNodeBoxSlack: a box that holds the nodes is all the test needs, and building it again
        // at every step cost 4 % of a forested run.
        std::optional<Eigen::AlignedBox3d> nodeBox;
        double nodeBoxSlack = 0;  // m: how far it was widened since it was built
        // Per node, where the soil's surface height was last asked for it, and that height (x, y,
        // height): with SoilBed::steepestRise it tells, without asking again, that a node moved a
        // few millimetres since is still too high to touch the soil (detectStemSoil).
        std::vector<Vec3> surfaceSeen;
        // Stepped at the last step: its velocities are the leapfrog's mid-step ones. Not when woken
        // nor once it rests: it then starts from rest (StemStart::FromRest).
        bool stepped = false;
        double lastBlockNear = -std::numeric_limits<double>::infinity();  // time the block last came within a step's approach
    };
    // Connections of two awake stems (indices into awake_) close enough to be checked each step.
    struct ConnectionPair {
        std::size_t a, b, connectionA, connectionB;
        // Checked while neither stem moved: until one does, the check would find what it found then.
        bool checkedStill = false;
    };
    // A block sphere against a stem, or against one piece of a broken stem (the deepest of its
    // connections this step).
    struct BlockStemTouch {
        // piece: the lowest connection of the stem's piece it touches (0: the standing stem); a
        // piece that breaks off above keeps the contacts on it (detectBlockStem). A node alone between
        // two breaks, or on top of a broken connection, is a piece named by the connection above it
        // (connectionCount() for the top node); its contact is on the broken connection below, t = 1.
        std::uint32_t blockSphere, tree, piece;
        std::size_t connection;
        double t;           // where along the connection
        double rawOverlap;  // before the onset offset: what picks the deepest connection
        ContactHistory history;
        ContactGeometry geometry;
        bool touching;
        std::size_t lastConnection;  // at the previous step
        double lastRawOverlap;
    };
    struct StemStemTouch {
        std::uint32_t treeA, treeB;
        std::size_t connectionA, connectionB;
        double s, t;
        ContactHistory history;
        ContactGeometry geometry;
        bool touching, ignored;  // ignored: connections fused at rest (the bases of a stool's stems)
    };
    struct StemSoilTouch {
        std::uint32_t tree, node, soil;
        ContactHistory history;
        ContactGeometry geometry;
        bool touching;
    };
    void wake(std::uint32_t tree, double t);
    AwakeStem* awake(std::uint32_t tree);  // null if asleep or never woken
    const AwakeStem* awake(std::uint32_t tree) const;
    void wakeNeighbours();
    void detectBlockStem(const RigidBody& block, const std::vector<Vec3>& centres, double approach);
    void listStemPairs();
    bool stemPairsStale() const;
    void detectStemStem();
    void detectStemSoil();
    void setMovingWhereTouched();
    void rest(AwakeStem& a);
    static Vec3 connectionVelocity(const Stem& s, std::size_t c, double t, const Vec3& point);
    static void applyToConnection(AwakeStem& a, std::size_t c, double t, const Vec3& point, const Vec3& force);

    const SceneConfig& cfg_;
    const TreeField& trees_;
    const SoilBed& soil_;
    StemActivity activity_;
    const ContactLaw* blockStemLaw_ = nullptr;
    const ContactLaw* stemStemLaw_ = nullptr;
    const ContactLaw* stemSoilLaw_ = nullptr;
    StemStepper stepper_;
    std::vector<AwakeStem> awake_;
    std::unordered_map<std::uint32_t, std::size_t> awakeSlot_;  // tree -> its index in awake_
    std::unordered_map<std::uint32_t, Stem> asleep_;  // stems woken before, kept as they were left
    ContactSet<BlockStemTouch> blockTouches_;
    ContactSet<StemStemTouch> stemTouches_;
    ContactSet<StemSoilTouch> soilTouches_;
    ImpactRecorder impacts_;
    std::vector<StemBreak> breaks_;
    std::vector<std::uint32_t> nearTrees_, nearSoil_;
    std::vector<Eigen::AlignedBox3d> boxes_;  // per awake stem (listStemPairs)
    std::vector<std::size_t> nearA_, nearB_;  // a pair's connections inside the other stem's box (listStemPairs)
    std::vector<ConnectionPair> stemPairs_;
    bool stemPairsStale_ = true;
    Islands islands_;  // of the awake stems, by stem/stem contact (sleep)
    std::vector<std::optional<StemAwake>> held_;  // per awake stem: what holds it (StemActivity::holds)
    std::vector<bool> reachedByNeighbour_;         // per awake stem: in neighbourReach_ as the one reached
    static constexpr double kStemPairSkin = 0.05;  // m
    static constexpr double kNodeBoxSlack = 0.05;  // m: a few block steps' travel, a hundred of a moving stem's
    DissipationLedger contactLedger_;
    ForestLedger slept_;        // ledgers of stems that went to sleep
    double frozenElastic_ = 0, frozenPotential_ = 0, injected_ = 0;
    double now_ = 0, lastDt_ = 0;
    static constexpr int kNeighbourCheckInterval = 10;
    int sinceNeighbourCheck_ = 0;
    // Found by the last neighbour check (wakeNeighbours): a moving stem and a stem one of its displaced
    // nodes could reach before the next. The two sleep together or not at all (sleep).
    struct NeighbourReach {
        std::uint32_t moving, reached;
    };
    std::vector<NeighbourReach> neighbourReach_;

    double budget_ = 0;
    NodeSteps nodeSteps_;
};

}  // namespace sylva::dem
