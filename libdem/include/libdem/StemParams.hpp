#pragma once
// Mechanical and discretisation parameters of a tree stem. Defaults are the paper's Table 2 (beech,
// Sect. 2.1.2) as read in model-notes.md; the choices the paper leaves open are marked.
#include <limits>

namespace sylva::dem {

// How Fig. 3 acts on the two bending axes (docs/model-stems.md argues the default).
enum class BendingReading {
    Isotropic,  // the trilinear law on the magnitude of the moment vector, direction following the rotation
    PerAxis,    // the paper's words: an independent trilinear law about x and about y of the connection frame
};

// What damps a stem's bending (BendingDamping; docs/model-stems.md, "Damping").
enum class StemDamping {
    Viscous,       // the paper's Eqs. 7-8: tau K_Elast times the relative rotation rate
    ConstantLoss,  // wood's internal friction: a loss factor independent of frequency
};

struct BendingParams {
    double moe = 8.7e9;          // MOE, Pa (Eq. 2)
    double ePlast = 2.1e9;       // E_Plast, Pa (Eq. 3)
    double eUnld = 5.3e9;        // E_Unld, Pa (Eq. 4)
    double sigmaElast = 37e6;    // sigma_Elast, Pa (Eq. 5)
    double sigmaRupt = 94e6;     // sigma_Rupt, Pa (Eq. 6)
    double tau = 5e-4;           // tau, s (Eqs. 7-8), for StemDamping::Viscous
    StemDamping damping = StemDamping::Viscous;
    double lossFactor = 0.02;    // eta = tan(delta) of green wood, for StemDamping::ConstantLoss
    // G_f, J per m^2 of the section broken: what a connection pays to break once M_Rupt is reached,
    // over a softening of its hinge (ConnectionFracture; docs/model-stems.md, "A fracture energy").
    // 0 is Eq. 6 as the paper has it, a brittle rupture that transmits nothing from the step M_Rupt
    // is reached.
    double fractureEnergy = 0;
    // Sections along each connection where Fig. 3 is applied (ConnectionBeam): 1 is the paper's
    // hinge at the connection's middle; 3 and 5 follow the moment's change along the connection.
    int sections = 1;
    BendingReading reading = BendingReading::Isotropic;
};

// How the root's yield moment M_a is set (docs/model-stems.md, "Anchorage").
enum class RootAnchorage {
    Fixed,        // the paper: M_a and K_Root the same for every tree
    StemWeight,   // winching tests: M_a = C_reg x stem mass, K_Root keeping the fixed M_a / K_Root rotation
};

struct RootSpringParams {
    double stiffness = 7.5e6;    // K_Root, N m/rad (Eqs. 9-10; Table 2's units are swapped, model-notes.md)
    double yieldMoment = 200e3;  // M_a, N m
    RootAnchorage anchorage = RootAnchorage::Fixed;
    double turningMomentPerKg = 120;  // C_reg, N m per kg of fresh stem, for RootAnchorage::StemWeight
    // Rotation of the foot (rad) at which the root plate lets go and carries no moment any more;
    // infinity: the paper's plateau at M_a without end.
    double failureRotation = std::numeric_limits<double>::infinity();
};

struct StemParams {
    BendingParams bending;
    RootSpringParams root;
    double density = 1200;       // fresh wood, kg/m^3
    double poisson = 0.3;        // nu: not in the paper; G = MOE / (2 (1 + nu))
    double nodeSpacing = 0.5;    // m, longest connection: the stem (up to its crown base, if graded) is cut into equal connections no longer than this
    // Blocks hit stems, hinges form and whipped boles break below the crown base. Above it (or above
    // `struckZone`, if that is higher) the stem mostly swings and may be cut coarser, at most
    // upperSpacingFactor x nodeSpacing apart. 1: the whole stem at nodeSpacing, as the paper's.
    // Refining the node spacing refines both parts. A resolution (docs/model-stems.md, "A graded stem").
    double upperSpacingFactor = 1;
    double struckZone = 4;  // m above the foot, the least height cut at nodeSpacing
    // The lowest footZone metres, where blocks strike stems (MO1 A: a tenth of the impacts below
    // 0.54 m), the root turns and the moment is largest, are cut at half nodeSpacing. Their
    // connections' axial and shear springs are softened, and their nodes' rotational inertia raised,
    // by the square of the ratio of the connection above the zone to theirs, so that they do not
    // shorten the explicit step. 0: none, as the paper's (Table 2's defaults here); else at least
    // nodeSpacing. The calibrated set's is 1 m (docs/model-stems.md, "The foot zone").
    double footZone = 0;
    double tipDiameter = 0.01;   // m, diameter of the truncated cone at H_T (docs/model-stems.md)
    // The axial springs' stiffness MOE A / l is divided by this. A numerical device, not wood: the
    // axial wave, l sqrt(rho / MOE), limits the explicit step while the bending allows 1.8-4.5 times more at 0.5 m,
    // and the axial strain of a struck stem is a few 1e-4. Results converge as it goes to 1
    // (docs/model-stems.md, "Time step": the axial springs softened).
    double axialSoftening = 1;
};

// Throws InputError naming the first parameter that is out of range.
void validate(const StemParams& p);

}  // namespace sylva::dem
