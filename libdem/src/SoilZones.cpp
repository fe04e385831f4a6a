#include "libdem/SoilZones.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "libcommon/InputError.hpp"

namespace sylva::dem {

std::size_t SoilZones::at(double x, double y) const {
    const int c = std::clamp(static_cast<int>(std::lround((x - x0) / cell)), 0, columns - 1);
    const int r = std::clamp(static_cast<int>(std::lround((y - y0) / cell)), 0, rows - 1);
    return zone[static_cast<std::size_t>(r) * columns + c];
}

ZonedSoilContact::ZonedSoilContact(std::shared_ptr<const SoilZones> zones, double blockMass) : zones_(std::move(zones)) {
    const SoilZones& z = *zones_;
    if (z.columns < 1 || z.rows < 1 || z.zone.size() != static_cast<std::size_t>(z.columns) * z.rows || z.names.size() != z.params.size())
        throw std::invalid_argument("ZonedSoilContact: a soil grid of " + std::to_string(z.zone.size()) + " cells for " +
                                    std::to_string(z.columns) + " x " + std::to_string(z.rows));
    for (std::size_t k = 0; k < z.params.size(); ++k) {
        try {
            laws_.emplace_back(z.params[k], blockMass);
        } catch (const InputError& e) {
            throw InputError("soil type '" + z.names[k] + "': " + e.what());
        }
        largestDamping_ = std::max(largestDamping_, laws_.back().dampingCoefficient());
        largestStiffness_ = std::max(largestStiffness_, z.params[k].kn);
    }
    for (const auto zone : z.zone)
        if (zone >= laws_.size()) throw std::invalid_argument("ZonedSoilContact: a cell of zone " + std::to_string(zone) + " of " + std::to_string(laws_.size()));
}

const SoilContact& ZonedSoilContact::lawAt(const ContactGeometry& g) const { return laws_[zones_->at(g.point.x(), g.point.y())]; }

Vec3 ZonedSoilContact::force(const ContactGeometry& g, ContactHistory& h, double dt, DissipationLedger& ledger) const {
    return lawAt(g).force(g, h, dt, ledger);
}

double ZonedSoilContact::storedEnergy(const ContactGeometry& g, const ContactHistory& h) const { return lawAt(g).storedEnergy(g, h); }

double ZonedSoilContact::normalStiffness(const ContactGeometry& g) const { return lawAt(g).normalStiffness(g); }

double ZonedSoilContact::dampingCoefficientAt(const ContactGeometry& g) const { return lawAt(g).dampingCoefficientAt(g); }

}  // namespace sylva::dem
