#pragma once
// The block's motion on the soil and through the forest, one explicit step at a time:
// detect contacts -> choose the stable time step -> contact forces -> integrate -> audit energy
// -> sleep; each phase timed (StepPhases).
#include <cstdint>
#include <vector>

#include "libdem/BlockRun.hpp"
#include "libdem/ContactSet.hpp"
#include "libdem/ForestMotion.hpp"
#include "libdem/StepHold.hpp"
#include "libdem/StepPhases.hpp"

namespace sylva::dem {

class BlockMotion {
public:
    // Throws InputError if the block starts inside the soil (or below its surface) or inside a stem,
    // or on a soil too soft to hold it (refuseSoilTooSoft).
    BlockMotion(const Scene& scene, const Release& start);
    // Throws InputError, naming the key, if the scene's soil (or a type of its soil map) is too soft
    // to hold the scene's block up: its weight on one contact would press it deeper than a soil
    // sphere's radius. Campaigns that go on past a run's bad release (hazard) ask it once, first.
    static void refuseSoilTooSoft(const Scene& scene);

    // Advances by one stable step (or the forced one) and returns it. Throws SimulationError on
    // NaN, on a forced step above the stable limit, or when energy grows without a source.
    double step();

    double time() const { return t_; }
    long steps() const { return steps_; }
    const PhaseTimes& phases() const { return phases_; }  // over the steps so far
    const NodeSteps& nodeSteps() const { return forest_.nodeSteps(); }
    RigidBody& block() { return block_; }  // e.g. to give the block an initial velocity
    const RigidBody& block() const { return block_; }
    bool touching() const { return !touches_.empty(); }
    std::size_t contactCount() const { return touches_.size(); }
    // Height of the block's lowest point above the macroscopic surface under its centre.
    double clearance() const;
    const EnergyBudget& energy() const { return budget_; }
    const ForestMotion& forest() const { return forest_; }
    ForestMotion& forest() { return forest_; }

private:
    // A block sphere touching a soil sphere, with the history its law carries between steps.
    struct SoilTouch {
        std::uint32_t blockSphere;
        std::uint32_t soilSphere;
        ContactHistory history;
        ContactGeometry geometry;
        bool touching;
    };

    void updateCentres();
    void detectContacts();
    double timeStep();
    void audit(const Vec3& force, const Vec3& torque, double dt, double soilStored, double forestTerm);
    // Throws InputError if a block sphere starts inside a standing stem.
    void refuseStartInsideStem(const Scene& scene) const;

    const SceneConfig& cfg_;
    const SoilBed& soil_;
    RigidBody block_;
    const ContactLaw& law_;
    std::vector<Vec3> worldCentres_;
    std::vector<std::uint32_t> candidates_;
    ContactSet<SoilTouch> touches_;
    double anticipatedStiffness_ = 0;
    StepHold stemStep_;  // the stems' step, held against a chattering bound
    DissipationLedger ledger_;
    EnergyBudget budget_;
    ForestMotion forest_;
    double lastBlockSide_ = 0, lastForestTerm_ = 0;  // the budget's two parts at the last audit
    double lastDt_ = 0;
    double t_ = 0;
    long steps_ = 0;
    PhaseTimes phases_;
};

}  // namespace sylva::dem
