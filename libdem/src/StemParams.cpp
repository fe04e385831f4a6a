#include "libdem/StemParams.hpp"

#include <cmath>
#include <string>

#include "libcommon/InputError.hpp"

namespace sylva::dem {

namespace {
void require(bool ok, const std::string& name, double value, const std::string& rule) {
    if (!ok) throw InputError("stem parameter " + name + " = " + std::to_string(value) + ": must be " + rule);
}
}  // namespace

void validate(const StemParams& p) {
    const BendingParams& b = p.bending;
    require(std::isfinite(b.moe) && b.moe > 0, "MOE (Pa)", b.moe, "> 0");
    require(std::isfinite(b.ePlast) && b.ePlast >= 0, "E_Plast (Pa)", b.ePlast, ">= 0");
    // The plastic branch dissipates only if unloading is stiffer than it (1 - K_Plast / K_Unld > 0).
    require(std::isfinite(b.eUnld) && b.eUnld > b.ePlast, "E_Unld (Pa)", b.eUnld, "> E_Plast");
    require(std::isfinite(b.sigmaElast) && b.sigmaElast > 0, "sigma_Elast (Pa)", b.sigmaElast, "> 0");
    require(std::isfinite(b.sigmaRupt) && b.sigmaRupt > b.sigmaElast, "sigma_Rupt (Pa)", b.sigmaRupt, "> sigma_Elast");
    require(b.sections == 1 || b.sections == 3 || b.sections == 5, "sections per connection", b.sections, "1, 3 or 5");
    require(std::isfinite(b.tau) && b.tau >= 0, "tau (s)", b.tau, ">= 0");
    require(std::isfinite(b.fractureEnergy) && b.fractureEnergy >= 0, "fracture energy G_f (J/m^2)", b.fractureEnergy, ">= 0");
    require(std::isfinite(b.lossFactor) && b.lossFactor >= 0 && b.lossFactor <= 0.5, "loss factor eta", b.lossFactor, "in [0, 0.5]");
    require(std::isfinite(p.root.stiffness) && p.root.stiffness > 0, "K_Root (N m/rad)", p.root.stiffness, "> 0");
    require(p.root.yieldMoment > 0, "M_a (N m)", p.root.yieldMoment, "> 0");
    require(std::isfinite(p.root.turningMomentPerKg) && p.root.turningMomentPerKg > 0, "C_reg (N m/kg)",
            p.root.turningMomentPerKg, "> 0");
    require(p.root.failureRotation > 0, "root failure rotation (rad)", p.root.failureRotation, "> 0");
    require(std::isfinite(p.density) && p.density > 0, "density (kg/m^3)", p.density, "> 0");
    require(p.poisson > -1 && p.poisson < 0.5, "Poisson ratio", p.poisson, "in (-1, 0.5)");
    require(std::isfinite(p.nodeSpacing) && p.nodeSpacing > 0, "node spacing (m)", p.nodeSpacing, "> 0");
    require(std::isfinite(p.upperSpacingFactor) && p.upperSpacingFactor >= 1, "upper spacing factor", p.upperSpacingFactor, ">= 1");
    require(std::isfinite(p.struckZone) && p.struckZone > 0, "struck zone (m)", p.struckZone, "> 0");
    // Shorter than the node spacing, its connections would be much shorter than half of it (0.3 m at
    // 0.5 m: two of 0.15 m), and their springs and inertia scaled by up to (l_c / l_f)^2 = 100.
    require(std::isfinite(p.footZone) && (p.footZone == 0 || p.footZone >= p.nodeSpacing), "foot zone (m)", p.footZone,
            "0 or at least the node spacing (" + std::to_string(p.nodeSpacing) + " m)");
    require(std::isfinite(p.tipDiameter) && p.tipDiameter >= 0, "tip diameter (m)", p.tipDiameter, ">= 0");
    require(std::isfinite(p.axialSoftening) && p.axialSoftening >= 1, "axial softening", p.axialSoftening, ">= 1");
}

}  // namespace sylva::dem
