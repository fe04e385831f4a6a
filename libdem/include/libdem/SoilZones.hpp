#pragma once
// Soil types over a terrain (a soil map): which block/soil contact parameters (Eqs. 14-19) hold where.
// The ground under a hazard map is scree here and forest soil there, as Rockyfor3D's soil classes and
// PlatRock's soil polygons have it; the contact at a soil sphere takes the law of the zone under the
// contact point.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "libdem/SoilContact.hpp"

namespace sylva::dem {

struct SoilZones {
    // Cell (c, r) is centred at (x0 + c cell, y0 + r cell), row 0 the southernmost (the terrain's frame).
    double x0 = 0, y0 = 0, cell = 1;
    int columns = 0, rows = 0;
    std::vector<std::uint16_t> zone;         // per cell, an index into names and params
    std::vector<std::string> names;          // of each zone, for messages and summaries
    std::vector<SoilContactParams> params;   // of each zone
    // The zone of the cell nearest (x, y), the edge cells' beyond the grid.
    std::size_t at(double x, double y) const;
};

// The block/soil (and stem/soil) law of each zone, chosen by where the contact point is.
class ZonedSoilContact final : public ContactLaw {
public:
    // InputError naming the zone for unusable parameters (SoilContact's checks); std::invalid_argument
    // for a grid whose size does not match its zones.
    ZonedSoilContact(std::shared_ptr<const SoilZones> zones, double blockMass);
    Vec3 force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const override;
    double storedEnergy(const ContactGeometry& g, const ContactHistory& h) const override;
    double normalStiffness(const ContactGeometry& g) const override;
    // The largest of the zones: one coefficient serves the whole block's stable step, which must hold on every soil.
    double dampingCoefficient() const override { return largestDamping_; }
    double dampingCoefficientAt(const ContactGeometry& g) const override;
    double largestNormalStiffness() const override { return largestStiffness_; }

private:
    const SoilContact& lawAt(const ContactGeometry& g) const;
    std::shared_ptr<const SoilZones> zones_;
    std::vector<SoilContact> laws_;
    double largestDamping_ = 0, largestStiffness_ = 0;
};

}  // namespace sylva::dem
