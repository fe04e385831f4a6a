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

// A stem and where it was planted: a stool's stems are told apart from a contact by their rest shape.
struct PlantedStem {
    const Stem& stem;
    const Vec3& foot;
};

// Whether connection `ca` of A and `cb` of B overlap in the stems' rest shape: a stool's stems stand
// so close that their cones meet near the foot, and there they are one fused stump, not a contact.
bool fusedAtRest(const PlantedStem& A, std::size_t ca, const PlantedStem& B, std::size_t cb);

// Whether intact connection `ca` of stem A touches intact connection `cb` of stem B, and where.
// A touch at a connection's lower node, where the intact connection below holds the same node, is
// that connection's: it finds the same touch, or a closer one, with a radius no smaller (stems taper
// upwards), so the node is counted once. Counted by both, a node bent against a neighbour pushed it
// twice as hard. Unless the connection below is fused with the other one (fusedAtRest): a fused
// pair takes no touch, so the node's stays with the connection above.
std::optional<ConnectionTouch> touchConnections(const PlantedStem& A, std::size_t ca, const PlantedStem& B, std::size_t cb);

}  // namespace sylva::dem
