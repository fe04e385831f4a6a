#pragma once
// The stem/stem narrow phase: two stem connections, cylinders of diameter D_con on their axes
// (Fig. 2), touch like the spheres inscribed at the closest points of those axes.
#include <cstddef>
#include <optional>

#include "libdem/ContactLaw.hpp"
#include "libdem/Stem.hpp"

namespace sylva::dem {

struct ConnectionTouch {
    double s, t;               // where along connection A and connection B, in [0, 1] from their lower node
    ContactGeometry geometry;  // normal from B to A, overlap, point, radii; velocities are the caller's
};

// Whether intact connection `ca` of stem A touches intact connection `cb` of stem B, and where.
// A touch at a connection's lower node, where the intact connection below holds the same node, is
// that connection's: it finds the same touch, or a closer one, with a radius no smaller (stems taper
// upwards), so the node is counted once. Counted by both, a node bent against a neighbour pushed it
// twice as hard.
std::optional<ConnectionTouch> touchConnections(const Stem& A, std::size_t ca, const Stem& B, std::size_t cb);

}  // namespace sylva::dem
