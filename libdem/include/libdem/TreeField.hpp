#pragma once
// The forest of a scene as plain data: where each stem stands, how big it is, and a grid to find
// the stems near a point. A stem becomes a mechanical object (a Stem) only when the block comes
// near it (BlockMotion wakes it); the other 99.9 % of a forest stay these few numbers.
#include <cstdint>
#include <vector>

#include "libdem/RigidBody.hpp"
#include "libdem/Stem.hpp"
#include "libdem/Terrain.hpp"
#include "libstand/Forest.hpp"
#include "libstand/Inventory.hpp"

namespace sylva::dem {

struct PlacedTree {
    long id;                 // stem id of the forest file
    Vec3 foot;               // on the terrain's macroscopic surface
    StemGeometry geometry;   // H_T, DBH, L_C, m_C (Eqs. 11-13)
    StemFoot support;        // coppice stems clamped, single trees on the root spring
};

// The same rule on an inventory the forests will be drawn from (assess, hazard --stands): a measured
// stem thinner than the tip diameter (m) is refused with its line in `stemsCsv`, before any forest is
// drawn or run stored, rather than as a virtual stem of the first forest that draws it.
void requireBuildableStems(const stand::Inventory& inventory, const std::string& stemsCsv, double tipDiameter);

class TreeField {
public:
    TreeField() = default;
    // Places every tree of the forest on the surface; throws InputError for a tree outside the terrain
    // or one too thin to be built as a stem (a DBH not above the stems' tip diameter, m).
    TreeField(const stand::Forest& forest, const SoilBed& soil, double tipDiameter);

    std::size_t size() const { return trees_.size(); }
    const PlacedTree& tree(std::size_t i) const { return trees_[i]; }
    double thickest() const { return thickest_; }  // largest DBH, m

    // Appends the indices of the trees whose foot lies within `radius` (horizontally) of (x, y).
    void near(double x, double y, double radius, std::vector<std::uint32_t>& out) const;

private:
    std::vector<PlacedTree> trees_;
    double thickest_ = 0;
    // Uniform grid over the trees' bounding box: cell (i, j) lists its trees in cellStart_.
    double x0_ = 0, y0_ = 0, cell_ = 5;
    int nx_ = 0, ny_ = 0;
    std::vector<std::uint32_t> cellStart_, cellTrees_;
};

}  // namespace sylva::dem
