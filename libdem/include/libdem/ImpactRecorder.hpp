#pragma once
// The record of every tree the block hits (TreeImpact), fed by the block/stem contacts as they
// begin and end. An impact opens at the block's first contact with a stem; its "after" is the
// block's state when that contact ends (a later contact with the standing stem, before the stem
// goes back to sleep, moves it on); it closes when the stem sleeps or the run ends.
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "libdem/BlockRun.hpp"
#include "libdem/RigidBody.hpp"
#include "libdem/Stem.hpp"
#include "libdem/TreeField.hpp"

namespace sylva::dem {

class ImpactRecorder {
public:
    // The stem of a tree (index into the TreeField) whose impact is open: it is awake.
    using StemOf = std::function<const Stem&(std::uint32_t tree)>;

    // Before the step's block/stem contacts are reported.
    void beginStep();
    // The block touches tree `tree` at `point` at time t; piece 0 is the standing stem, others are
    // pieces broken off it. Only the standing stem opens an impact or starts a contact of one.
    void touch(const RigidBody& block, std::uint32_t tree, const PlacedTree& placed, std::uint32_t piece, const Vec3& point,
               double t, const Stem& stem);
    // After the step's contacts: the impacts whose contact ended take the block's state as "after".
    void endStep(const RigidBody& block, const StemOf& stemOf);
    bool isOpen(std::uint32_t tree) const { return openOf_.count(tree) > 0; }
    // The stem goes to sleep: its impact (if open) closes with the stem's outcome.
    void close(std::uint32_t tree, const RigidBody& block, const Stem& stem);
    // Closes every open impact; all records, in the order they began.
    std::vector<TreeImpact> finish(const RigidBody& block, const StemOf& stemOf);

private:
    struct Impact {
        TreeImpact record;
        std::uint32_t tree;  // index into the TreeField
        bool open;
        bool inContact;             // the block touches the stem now; "after" is taken when this ends
        bool wasInContact;          // ... and did at the previous step
        StemLedger atFirstContact;  // the stem's ledger when the impact began
    };
    void takeAfter(Impact& i, const RigidBody& block, const Stem& stem);
    void closeAt(std::size_t index, const RigidBody& block, const Stem& stem);

    std::vector<Impact> impacts_;
    std::unordered_map<std::uint32_t, std::size_t> openOf_;  // tree -> index in impacts_
};

}  // namespace sylva::dem
