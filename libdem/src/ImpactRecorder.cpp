#include "libdem/ImpactRecorder.hpp"

#include <algorithm>

namespace sylva::dem {

void ImpactRecorder::beginStep() {
    for (auto& [tree, index] : openOf_) {
        impacts_[index].wasInContact = impacts_[index].inContact;
        impacts_[index].inContact = false;
    }
}

void ImpactRecorder::touch(const RigidBody& block, std::uint32_t tree, const PlacedTree& placed, std::uint32_t piece,
                           const Vec3& point, double t, const Stem& stem) {
    auto open = openOf_.find(tree);
    if (open == openOf_.end()) {
        // A piece broken off the stem is debris, not an impact: it opens none, also when it meets
        // the block after its stem slept and was woken again (the impact closed then).
        if (piece != 0) return;
        TreeImpact r;
        r.tree = placed.id;
        r.time = t;
        r.speedBefore = block.velocity.norm();
        r.energyBefore = block.kineticEnergy();
        r.height = point.z() - placed.foot.z();
        // Lateral offset of the block's centre from the stem's axis, across its horizontal motion,
        // relative to the largest offset at which they can touch.
        const Vec3 v(block.velocity.x(), block.velocity.y(), 0);
        const Vec3 w = block.position - placed.foot;
        const double lateral = v.norm() > 0 ? (v.x() * w.y() - v.y() * w.x()) / v.norm() : 0;
        r.eccentricity = std::clamp(lateral / (block.boundingRadius() + 0.5 * placed.geometry.dbh), -1.0, 1.0);
        open = openOf_.emplace(tree, impacts_.size()).first;
        impacts_.push_back({r, tree, true, true, false, stem.ledger});
    }
    Impact& i = impacts_[open->second];
    // A piece broken off the stem that falls on the block once it has left the tree is debris,
    // not the impact: only the standing stem (piece 0) starts a new contact.
    if (i.wasInContact || piece == 0) i.inContact = true;
}

void ImpactRecorder::endStep(const RigidBody& block, const StemOf& stemOf) {
    for (auto& [tree, index] : openOf_) {
        Impact& i = impacts_[index];
        if (!i.inContact && i.wasInContact) takeAfter(i, block, stemOf(tree));
    }
}

void ImpactRecorder::takeAfter(Impact& i, const RigidBody& block, const Stem& stem) {
    i.record.speedAfter = block.velocity.norm();
    i.record.energyAfter = block.kineticEnergy();
    i.record.duringImpact = stem.ledger.since(i.atFirstContact);
}

void ImpactRecorder::close(std::uint32_t tree, const RigidBody& block, const Stem& stem) {
    const auto open = openOf_.find(tree);
    if (open != openOf_.end()) closeAt(open->second, block, stem);
}

void ImpactRecorder::closeAt(std::size_t index, const RigidBody& block, const Stem& stem) {
    Impact& i = impacts_[index];
    i.record.stemBroken = stem.anyConnectionBroken();
    i.record.breakHeight = stem.lowestBreakHeight();
    i.record.stemBreaks = stem.breakCount();
    i.record.stemHeight = stem.geometry().height;
    i.record.rootYielded = stem.ledger.rootPlasticity > 0;
    i.record.rootFailed = stem.root().failed();
    if (i.inContact) takeAfter(i, block, stem);  // still touching when the run ends: "after" is now
    openOf_.erase(i.tree);
    i.open = false;
}

std::vector<TreeImpact> ImpactRecorder::finish(const RigidBody& block, const StemOf& stemOf) {
    std::vector<TreeImpact> out;
    out.reserve(impacts_.size());
    for (std::size_t k = 0; k < impacts_.size(); ++k) {
        if (impacts_[k].open) closeAt(k, block, stemOf(impacts_[k].tree));
        out.push_back(impacts_[k].record);
    }
    return out;
}

}  // namespace sylva::dem
