#include "libdem/SceneConfig.hpp"

#include <boost/program_options.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>

#include "libdem/OptionErrorMessage.hpp"
#include "libdem/StemParameterSet.hpp"
#include "libcommon/InputError.hpp"
#include "libcommon/LineEnds.hpp"

namespace sylva::dem {

namespace po = boost::program_options;

namespace {

template <class T>
std::string text(const T& v) {
    std::ostringstream os;
    os << v;  // shortest readable form (0.7, not 0.69999999999999996)
    return os.str();
}

// The physical range of a numeric key. A value outside it is refused where it is read, before
// anything is built from it, with the key, the value, the range and the likely cause.
struct Range {
    double lo, hi;
    bool loOpen, hiOpen;
    const char* unit;
    const char* tooLow = "";   // likely cause of a value below the range
    const char* tooHigh = "";  // ... above it
    bool infinityMeansNever = false;  // +inf is accepted: the key's "never"
};
Range closed(double lo, double hi, const char* unit, const char* tooLow = "", const char* tooHigh = "") {
    return {lo, hi, false, false, unit, tooLow, tooHigh};
}
Range aboveUpTo(double lo, double hi, const char* unit, const char* tooLow = "", const char* tooHigh = "") {
    return {lo, hi, true, false, unit, tooLow, tooHigh};  // (lo, hi]
}
Range fromBelow(double lo, double hi, const char* unit) { return {lo, hi, false, true, unit}; }  // [lo, hi)

std::string describe(const Range& r) {
    std::string s = std::string(r.loOpen ? "(" : "[") + text(r.lo) + ", " + text(r.hi) + (r.hiOpen ? ")" : "]");
    return *r.unit ? s + " " + r.unit : s;
}

bool inside(const Range& r, double v) {
    if (r.infinityMeansNever && v == std::numeric_limits<double>::infinity()) return true;
    return std::isfinite(v) && (r.loOpen ? v > r.lo : v >= r.lo) && (r.hiOpen ? v < r.hi : v <= r.hi);
}

struct NumericKey {
    std::string name;
    const double* value;
    Range range;
};

// One table of keys: name, target, default, meaning, and for numbers their range (shown in
// --help-scene). The INI sections are the part before the dot.
class KeyTable {
public:
    KeyTable() : keys_("Scene keys ([section] key = value, or --set section.key=value); [range] of each number") {}

    void number(const char* key, double& v, const Range& r, const std::string& meaning) {
        keys_.add_options()(key, po::value(&v)->default_value(v, text(v)), (meaning + " " + describe(r)).c_str());
        numbers_.push_back({key, &v, r});
    }
    // A number without a default: absent means "not used" (a cuboid's edges, a launch speed).
    void optionalNumber(const char* key, double& v, const Range& r, const std::string& meaning) {
        keys_.add_options()(key, po::value(&v), (meaning + " " + describe(r)).c_str());
        numbers_.push_back({key, &v, r});
    }
    template <class T>
    void other(const char* key, T& v, const char* meaning) {
        keys_.add_options()(key, po::value(&v)->default_value(v, text(v)), meaning);
    }
    template <class T>
    void optionalOther(const char* key, T& v, const char* meaning) {
        keys_.add_options()(key, po::value(&v), meaning);
    }
    const po::options_description& keys() const { return keys_; }
    const std::vector<NumericKey>& numbers() const { return numbers_; }

private:
    po::options_description keys_;
    std::vector<NumericKey> numbers_;
};

// The scene's keys bound to one configuration, with the keys read as text or in other units.
struct SceneKeys {
    SceneConfig c;
    std::string shape = "cube", orientation = "random", reading = "isotropic", damping = "viscous", anchorage = "fixed",
                treeReach = "block";
    double restitution = 0;  // used only when soil.restitution is given
    double rootFailureDeg = 0;  // stem.root_failure_rotation_deg
    std::string parameterSet;   // stem.parameters
    KeyTable table;

    // The defaults are those of a named parameter set for the stems, which the keys then change.
    explicit SceneKeys(StemParameterSet set = StemParameterSet::Calibrated);
    SceneKeys(const SceneKeys&) = delete;  // the table points into this object
    SceneKeys& operator=(const SceneKeys&) = delete;
};

SceneKeys::SceneKeys(StemParameterSet set) : parameterSet(name(set)) {
    apply(set, c.stem, c.stemContact);
    c.stemParameters = parameterSet;
    damping = c.stem.bending.damping == StemDamping::Viscous ? "viscous" : "constant_loss";
    anchorage = c.stem.root.anchorage == RootAnchorage::Fixed ? "fixed" : "stem_weight";
    rootFailureDeg = c.stem.root.failureRotation * 180 / std::acos(-1.0);
    KeyTable& k = table;
    auto& t = c.terrain;
    auto& s = c.soilContact;
    auto& b = c.block;
    auto& r = c.release;
    auto& i = c.integration;
    auto& st = c.stop;
    auto& stem = c.stem;
    auto& bend = c.stem.bending;
    auto& tc = c.stemContact;
    auto& act = c.activity;
    // Map coordinates: a projected CRS (UTM northings reach 1e7 m) or the scene's own frame.
    const Range coordinate = closed(-1e8, 1e8, "m");
    const Range modulus = closed(1e5, 1e13, "Pa", "MPa or GPa typed as Pa?");
    const Range ratio = aboveUpTo(0, 10, "");
    const Range friction = fromBelow(0, 90, "deg");
    k.optionalOther("terrain.profile", t.profile, "slope profile CSV with columns x,z (m), x increasing and the slope falling along it (run-out is measured along +x), no step both steeper than 89 degrees and higher than 2 000 m (a NODATA value left in it), relative to the scene file");
    k.optionalOther("terrain.dtm", t.dtm, "or a DTM as an ESRI ASCII grid (.asc)");
    k.optionalOther("forest.file", c.forestFile, "forest CSV (from sylvarock generate, or x,y,dbh_cm[,stool]); relative to the scene file");
    k.number("terrain.width_m", t.soil.width, aboveUpTo(0, 5000, "m", "", "the soil bed covers the whole width: a valley-wide strip would not fit in memory"), "extent across the slope of a profile terrain");
    k.number("terrain.soil_radius_m", t.soil.radius, aboveUpTo(0.01, 10, "m", "", "cm typed as m?"), "R_soil (Sect. 2.1.1: 0.7)");
    k.number("terrain.roughness_m", t.soil.roughness, aboveUpTo(0, 10, "m", "", "cm typed as m?"), "bump height between soil spheres (Table 2: 0.1)");
    k.other("terrain.seed", t.soil.seed, "seed of the rows' offsets across the slope (Fig. 7) and of a DTM's micro-topography");
    k.number("terrain.microtopography_m", t.micro.sigma, closed(0, 10, "m", "", "cm typed as m?"),
             "DTM terrains: standard deviation of a seeded relief added at the DTM's cells (0: the DTM as it is; docs/hazard.md)");
    k.number("terrain.microtopography_length_m", t.micro.lengthM, aboveUpTo(0, 1000, "m"), "its correlation length (the stand-in slope's: 6)");
    k.number("soil.kn_n_m", s.kn, aboveUpTo(0, 1e12, "N/m"), "K_n^soil (Table 2)");
    k.number("soil.kappa", s.kappa, ratio, "K_t/K_n (Eq. 19)");
    k.number("soil.damping_ratio", s.dampingRatio, fromBelow(0, 1, ""), "alpha/alpha_cr (Eq. 15)");
    k.optionalNumber("soil.restitution", restitution, aboveUpTo(0, 1, ""), "e_n instead of damping_ratio (Eq. 15)");
    k.other("soil.dashpot_pulls", s.dashpotPulls, "Eq. 14 as written (true: the dashpot may pull at the end of a rebound) or floored at zero (false, as Yade)");
    k.number("soil.friction_deg", s.frictionDeg, friction, "phi^soil");
    k.other("block.shape", shape, "cube | cuboid | sphere");
    k.number("block.volume_m3", b.volumeM3, aboveUpTo(0, 1000, "m^3", "", "litres typed as m^3? (above 1000 m^3 is a rock avalanche, not a rockfall)"), "volume of a cube or sphere block");
    const Range edge = aboveUpTo(0, 20, "m", "", "mm or cm typed as m?");
    k.optionalNumber("block.d1_m", b.d1, edge, "cuboid edge 1; on a cube, its edge: the volume is then d1^3 (a block.volume_m3 given beside it must agree, one in the file gives way to d1_m on --set)");
    k.optionalNumber("block.d2_m", b.d2, edge, "cuboid edge 2");
    k.optionalNumber("block.d3_m", b.d3, edge, "cuboid edge 3");
    k.number("block.density_kg_m3", b.densityKgM3, closed(500, 8000, "kg/m^3", "t/m^3 typed as kg/m^3?"), "(Table 2: 2700)");
    k.number("release.x_m", r.x, coordinate, "release x");
    k.number("release.y_m", r.y, coordinate, "release y (runs without forest)");
    k.optionalNumber("release.y_min_m", r.yMin, coordinate, "release y drawn uniformly in [y_min_m, y_max_m]");
    k.optionalNumber("release.y_max_m", r.yMax, coordinate, "");
    k.number("release.forest_y_min_m", r.forestYMin, coordinate, "with a forest and no y range: y uniform in [forest_y_min_m, forest_y_max_m] (Sect. 2.3.2)");
    k.number("release.forest_y_max_m", r.forestYMax, coordinate, "");
    k.number("release.fall_height_m", r.fallHeight, aboveUpTo(0, 1000, "m"), "block centre above the surface, clear of the soil (more than the block's half-size above it)");
    k.other("release.orientation", orientation, "random (angles in [0,180) deg about x,y,z) | fixed");
    k.optionalNumber("block.speed_m_s", c.launch.speed, closed(0, 100, "m/s", "", "km/h typed as m/s? (rockfall rarely exceeds 40 m/s)"), "single-tree scenes: launch the block at this speed toward the tree (+x)");
    k.number("block.impact_height_m", c.launch.impactHeight, aboveUpTo(0, 30, "m", "", "cm typed as m?"), "... its centre this high above the stem's foot");
    k.number("block.eccentricity", c.launch.eccentricity, closed(-1, 1, ""), "... offset across its path by this fraction of (block radius + stem radius)");
    k.number("block.launch_distance_m", c.launch.distance, closed(0, 100, "m"), "... starting this far before the stem's axis");
    k.optionalNumber("tree.dbh_cm", c.tree.dbhCm, aboveUpTo(0, 300, "cm", "", "DBH typed in mm?"), "single-tree scenes: one tree of this DBH (replaces forest.file)");
    k.number("tree.x_m", c.tree.x, coordinate, "its position");
    k.number("tree.y_m", c.tree.y, coordinate, "");
    k.other("tree.coppice", c.tree.coppice, "a coppice stem (clamped foot) instead of a single tree (root spring)");
    k.number("integration.safety", i.safety, aboveUpTo(0, 1, ""), "time step as a fraction of the stable limit");
    k.number("integration.stem_safety", i.stemSafety, aboveUpTo(0, 1, ""), "time step as a fraction of the awake stems' stable limit");
    k.number("integration.dt_s", i.forcedDt, closed(0, 1, "s"), "force this time step (0: automatic); refused if unstable");
    k.other("integration.anticipated_contacts", i.anticipatedContacts, "new contacts the step must stay stable for (1 to 1000)");
    k.number("integration.energy_tolerance", i.energyTolerance, aboveUpTo(0, 1, "(fraction)", "", "a percentage typed as a fraction? 0.5 is 50 %"), "relative energy growth that stops a run");
    k.number("integration.energy_warning", i.energyWarning, aboveUpTo(0, 1, "(fraction)", "", "a percentage typed as a fraction? 0.05 is 5 %"), "relative energy imbalance above which a run is flagged (runs.csv energy_flag, summary.json energy_flagged_runs)");
    k.number("stop.rest_distance_m", st.restDistance, aboveUpTo(0, 100, "m"), "the block rests once its centre stays within this distance of one point ...");
    k.number("stop.rest_time_s", st.restTime, aboveUpTo(0, 3600, "s"), "... for this long");
    k.number("stop.max_time_s", st.maxTime, aboveUpTo(0, 1e5, "s"), "simulated time limit");
    k.other("stem.parameters", parameterSet, "named set of the tree's parameters, the defaults of the stem.* and tree_contact.* keys: calibrated (converged in the node spacing, anchorage from winching tests) | toe2018 (the paper's Table 2 and stem, to rerun its study); docs/model-stems.md");
    k.number("stem.node_spacing_m", stem.nodeSpacing, aboveUpTo(0.005, 5, "m", "mm typed as m?"), "largest distance between a stem's nodes");
    k.number("stem.upper_spacing_factor", stem.upperSpacingFactor, closed(1, 20, ""), "in the crown (above the crown base, or above stem.struck_zone_m if that is higher), where a stem mostly swings, its nodes are up to this times stem.node_spacing_m apart; 1 (the default): the whole stem at stem.node_spacing_m; 2 runs MO1 A in 0.8 of the CPU and a study in 0.88, PF50 within sampling error, but moves some slow single-tree impacts at half the spacing past 5 % (docs/model-stems.md, \"A graded stem\")");
    k.number("stem.foot_zone_m", stem.footZone, closed(0, 100, "m"), "the lowest metres of a stem, where blocks strike, the root turns and the moment is largest, cut at half stem.node_spacing_m, their axial and shear springs softened and their nodes' rotational inertia raised so that the stems' step stays that of the coarser connections; 0: none, else at least stem.node_spacing_m (calibrated: 1, or the node spacing if coarser; toe2018: 0); with 1 m the single-tree matrix's block exit energies agree within 5 % between 0.5 and 0.25 m in 133 of 144 impacts against 121 without (45 against 36 of the 48 struck 0.5 m up), and MO1 A's PF50 at 0.5 m is 0.022 below the zone's at 0.25 m and the uniform stem's 0.041 below it (3 200 runs each), for 1.1-1.2 times the CPU (docs/model-stems.md, \"The foot zone\")");
    k.number("stem.struck_zone_m", stem.struckZone, aboveUpTo(0, 100, "m"), "with stem.upper_spacing_factor > 1, a stem is cut at stem.node_spacing_m up to its crown base (where whipped boles break), and at least up to this height above the foot (where blocks strike stems and their hinges form)");
    k.number("stem.tip_diameter_m", stem.tipDiameter, closed(0, 0.5, "m", "", "cm typed as m?"), "diameter of the cone at H_T");
    k.number("stem.axial_softening", stem.axialSoftening, closed(1, 100, ""), "the axial springs' MOE A / l divided by this, a resolution like the node spacing: the axial wave, not the bending, limits the stems' step; 1 is wood's (toe2018), results converge towards it (docs/model-stems.md)");
    k.number("stem.density_kg_m3", stem.density, closed(200, 2000, "kg/m^3", "t/m^3 typed as kg/m^3?"), "fresh wood (Table 2: 1.2 t/m^3)");
    k.number("stem.poisson", stem.poisson, {-1, 0.5, true, true, ""}, "nu, for shear and twist (not in the paper)");
    k.number("stem.moe_pa", bend.moe, modulus, "MOE (Eq. 2)");
    k.number("stem.e_plast_pa", bend.ePlast, closed(0, 1e12, "Pa"), "E_Plast (Eq. 3)");
    k.number("stem.e_unld_pa", bend.eUnld, modulus, "E_Unld (Eq. 4)");
    k.number("stem.sigma_elast_pa", bend.sigmaElast, closed(1e4, 1e10, "Pa", "MPa typed as Pa?"), "sigma_Elast (Eq. 5)");
    k.number("stem.sigma_rupt_pa", bend.sigmaRupt, closed(1e4, 1e10, "Pa", "MPa typed as Pa?"), "sigma_Rupt (Eq. 6)");
    k.other("stem.sections", bend.sections, "sections per connection where Fig. 3 acts: 1 (the paper: at the connection's middle) | 3 | 5 (along the connection, where the moment changes; docs/model-stems.md)");
    k.number("stem.tau_s", bend.tau, closed(0, 1, "s", "", "ms typed as s?"), "tau (Eqs. 7-8), for stem.damping = viscous");
    k.other("stem.damping", damping, "viscous (the paper's Eqs. 7-8) | constant_loss (wood's loss factor, independent of frequency; docs/model-stems.md)");
    k.number("stem.loss_factor", bend.lossFactor, closed(0, 0.5, "", "", "percent typed as a fraction?"), "eta = tan(delta) of green wood, for stem.damping = constant_loss");
    k.number("stem.fracture_energy_j_m2", bend.fractureEnergy, closed(0, 1e6, "J/m^2", "", "a strength in Pa typed for an energy in J/m^2?"), "G_f: what a connection pays, per m^2 of its section, to break once M_Rupt is reached, over a softening of its hinge (green spruce across the grain: at most about 5e4, from impact-bending work; docs/model-stems.md, \"What G_f is, measured\"); 0 (the default): Eq. 6's brittle rupture, under which a whipped stem breaks into more pieces the finer its nodes (docs/model-stems.md, \"A fracture energy\")");
    k.other("stem.bending_reading", reading, "isotropic (moment vector) | per_axis (the paper's x and y laws)");
    k.number("stem.root_stiffness_nm_rad", stem.root.stiffness, aboveUpTo(0, 1e12, "N m/rad"), "K_Root (Eqs. 9-10)");
    k.number("stem.root_yield_moment_nm", stem.root.yieldMoment, aboveUpTo(0, 1e9, "N m", "", "N mm typed as N m?"), "M_a, for stem.anchorage = fixed");
    k.other("stem.anchorage", anchorage, "fixed (the paper: M_a and K_Root for every tree) | stem_weight (M_a = C_reg x stem mass, winching tests; docs/model-stems.md)");
    k.number("stem.root_turning_moment_nm_per_kg", stem.root.turningMomentPerKg, aboveUpTo(0, 1e4, "N m/kg"), "C_reg, for stem.anchorage = stem_weight");
    Range rootFailure = aboveUpTo(0, 180, "deg");
    rootFailure.infinityMeansNever = true;  // documented, and the only way to keep the paper's plateau in the calibrated set
    k.number("stem.root_failure_rotation_deg", rootFailureDeg, rootFailure,
             "rotation of the foot at which the root plate lets go (inf: never, the paper's plateau at M_a)");
    k.number("tree_contact.er_pa", tc.woodRadialModulus, modulus, "E_r (Eqs. 22-23)");
    k.number("tree_contact.eb_pa", tc.blockModulus, modulus, "E_b (Eq. 22)");
    k.number("tree_contact.kappa_block_stem", tc.kappaBlockStem, ratio, "kappa_b-t");
    k.number("tree_contact.friction_block_stem_deg", tc.frictionBlockStemDeg, friction, "phi_b-t");
    k.number("tree_contact.crushing_strength_pa", tc.crushingStrength, closed(0, 1e9, "Pa"),
             "wood's compression strength across the grain: the stem crushes under the block (0: the paper's elastic contact)");
    k.number("tree_contact.kappa_stem_stem", tc.kappaStemStem, ratio, "kappa_t-t");
    k.number("tree_contact.friction_stem_stem_deg", tc.frictionStemStemDeg, friction, "phi_t-t");
    k.number("forest.wake_margin_m", act.wakeMargin, closed(0, 100, "m"), "a stem is built when the block comes this close");
    k.number("forest.return_horizon_s", act.returnHorizon, closed(0, 3600, "s"), "a stem the block has left stops where it stands once the block could not reach it within this time (single-tree.ini: 3600, never)");
    k.number("forest.sleep_after_s", act.sleepAfter, aboveUpTo(0, 3600, "s"), "a stem sleeps after this long without the block");
    k.number("forest.piece_rest_speed_m_s", act.pieceRestSpeed, aboveUpTo(0, 100, "m/s"), "a broken stem sleeps, and a stem lying on the soil or a neighbour rests, only once all its nodes are slower than this");
    k.number("forest.piece_max_time_s", act.pieceMaxTime, closed(0, 3600, "s"), "... or this long after the block's last contact (0: broken stems sleep as whole ones; single-tree.ini: 10)");
    k.other("forest.all_awake", act.allAwake, "reference mode: every stem awake from the start");
    auto& lm = c.lumped;
    const Range obstacle = closed(0, 10, "m", "", "cm typed as m?");
    k.other("lumped.soil_type", lm.soilType, "lumped model (--model lumped): Rockyfor3D soil type 0-7 setting R_n (Table 1: 4, talus slope; docs/lumped.md)");
    k.number("lumped.rg70_m", lm.rg70, obstacle, "mean obstacle height met by 70 % of the rebounds (Table 1: 0.04)");
    k.number("lumped.rg20_m", lm.rg20, obstacle, "... by 20 %");
    k.number("lumped.rg10_m", lm.rg10, obstacle, "... by 10 %");
    k.number("lumped.slope_baseline_m", lm.slopeBaseline, aboveUpTo(0.01, 100, "m"), "finite-difference baseline of the slope under a rebound (below the terrain resolution: the facet's own normal)");
    k.number("lumped.deviation_sd_deg", lm.deviationSdDeg, closed(0, 90, "deg"), "random turn of the direction at a rebound (standard deviation)");
    k.number("lumped.stop_speed_m_s", lm.stopSpeed, aboveUpTo(0, 10, "m/s"), "a block slower than this has stopped");
    k.number("lumped.tree_energy_scale", lm.treeEnergyScale, closed(0, 100, ""), "scales the energy a tree takes (1: Dorren & Berger 2006)");
    k.other("lumped.tree_reach", treeReach, "block (a tree is hit when the block's centre passes within R + DBH/2 of its axis, the paper's Sect. 2.3.1) | centre (within DBH/2: how Rockyfor3D's code detected impacts before its v6.0; docs/lumped.md)");
    k.number("gravity_m_s2", c.gravity, aboveUpTo(0, 100, "m/s^2"), "");
    k.number("output.trajectory_interval_s", c.trajectoryInterval, aboveUpTo(0, 3600, "s"), "trajectory sampling");
}

// Line of `key` ("section.key") in an INI file's text, 0 if not found: errors point at it.
long lineOf(const std::string& text, const std::string& key, int occurrence = 1) {
    const auto dot = key.rfind('.');
    const std::string section = dot == std::string::npos ? "" : key.substr(0, dot);
    const std::string name = key.substr(dot == std::string::npos ? 0 : dot + 1);
    std::istringstream in(text);
    std::string line, current;
    for (long n = 1; std::getline(in, line); ++n) {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos) continue;
        if (line[first] == '[') {
            const auto close = line.find(']', first);
            current = line.substr(first + 1, close == std::string::npos ? std::string::npos : close - first - 1);
        } else if (current == section && line.compare(first, name.size(), name) == 0) {
            const auto rest = line.find_first_not_of(" \t", first + name.size());
            if (rest != std::string::npos && line[rest] == '=' && --occurrence == 0) return n;
        }
    }
    return 0;
}

// A refusal of `key` names where it was given: on --set (`fromSet`), or at its line of the file
// `path`, whose text is `fileText`.
InputError keyError(const std::string& key, const std::string& what, const std::set<std::string>& fromSet,
                    const std::string* path, const std::string& fileText) {
    if (fromSet.count(key) || !path) return InputError("--set " + what);
    return InputError(*path, lineOf(fileText, key), what);
}

// Each number given (not defaulted) must lie in its range.
void checkRanges(const KeyTable& k, const po::variables_map& vm, const std::set<std::string>& fromSet,
                 const std::string* path, const std::string& fileText) {
    for (const NumericKey& n : k.numbers()) {
        const auto it = vm.find(n.name);
        if (it == vm.end() || it->second.defaulted() || inside(n.range, *n.value)) continue;
        const double v = *n.value;
        std::string what = n.name + " = " + text(v) + ": ";
        what += std::isfinite(v) ? "outside " : "not a finite number; it must lie in ";
        what += describe(n.range);
        const char* hint = !std::isfinite(v) ? "" : v <= n.range.lo ? n.range.tooLow : n.range.tooHigh;
        if (*hint) what += std::string(" (") + hint + ")";
        throw keyError(n.name, what, fromSet, path, fileText);
    }
}

// Keys without a section (gravity_m_s2) come first: after another key's [section] line they
// would be read as that section's.
std::string overridesAsIni(const std::vector<std::string>& overrides) {
    std::string top, sections;
    for (const auto& o : overrides) {
        const auto eq = o.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError("--set '" + o + "': expected section.key=value");
        const std::string key = o.substr(0, eq);
        const auto dot = key.rfind('.');
        if (dot == std::string::npos) top += key + "=" + o.substr(eq + 1) + "\n";
        else sections += "[" + key.substr(0, dot) + "]\n" + key.substr(dot + 1) + "=" + o.substr(eq + 1) + "\n";
    }
    return top + sections;
}

// The scene file's text, a UTF-8 byte-order mark (which some editors write) removed, its lines ended
// by line feeds (LineEnds.hpp).
std::string sceneText(const std::string& path) {
    if (std::filesystem::is_directory(path)) throw InputError(path, 0, "is a folder, not a scene file");
    std::ifstream in(path);
    if (!in) throw InputError(path, 0, "cannot open scene file");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    return withCrOnlyLineEndsAsLineFeeds(std::move(text));
}

// The line of the file holding `content` (its spaces trimmed), 0 if none: program_options names an
// unreadable line by its text only.
long lineHolding(const std::string& text, const std::string& content) {
    std::istringstream lines(text);
    std::string line;
    for (long n = 1; std::getline(lines, line); ++n) {
        const auto first = line.find_first_not_of(" \t\r"), last = line.find_last_not_of(" \t\r");
        if (first != std::string::npos && line.substr(first, last - first + 1) == content) return n;
    }
    return 0;
}

// The value of stem.parameters (--set over the file, whose text is `text`), read first: it sets the
// other keys' defaults.
StemParameterSet parameterSetOf(const std::string* path, const std::string& text, const std::vector<std::string>& overrides) {
    po::options_description d;
    std::string set = "calibrated";
    d.add_options()("stem.parameters", po::value(&set)->default_value(set));
    po::variables_map vm;
    bool fromSet = false;
    try {
        std::istringstream setIni(overridesAsIni(overrides));
        po::store(po::parse_config_file(setIni, d, true), vm);
        fromSet = !vm["stem.parameters"].defaulted();
        if (path) {
            std::istringstream in(text);
            po::store(po::parse_config_file(in, d, true), vm);
        }
    } catch (const po::error&) {
        return StemParameterSet::Calibrated;  // the full parse below reports it with its context
    }
    po::notify(vm);
    try {
        return parseStemParameterSet(set);
    } catch (const InputError& e) {
        if (fromSet || !path) throw InputError(std::string("--set ") + e.what());
        throw InputError(*path, lineOf(text, "stem.parameters"), e.what());
    }
}

SceneConfig load(const std::string* path, const std::vector<std::string>& overrides) {
    const std::string fileText = path ? sceneText(*path) : std::string();  // read once, for both parses
    SceneKeys keys(parameterSetOf(path, fileText, overrides));
    SceneConfig& c = keys.c;
    const std::string &shape = keys.shape, &orientation = keys.orientation, &reading = keys.reading, &damping = keys.damping,
                      &anchorage = keys.anchorage, &treeReach = keys.treeReach;
    const po::options_description& d = keys.table.keys();
    po::variables_map vm;
    std::istringstream setIni(overridesAsIni(overrides));
    std::set<std::string> fromSet;
    try {
        const po::parsed_options given = po::parse_config_file(setIni, d);
        for (const auto& o : given.options) fromSet.insert(o.string_key);
        po::store(given, vm);  // first stored wins: --set over the file
    } catch (const po::error& e) {
        throw InputError(std::string("--set: ") + optionErrorMessage(e));
    }
    if (path) {
        std::istringstream in(fileText);
        try {
            po::store(po::parse_config_file(in, d), vm);
        } catch (const po::error& e) {
            const std::string message = optionErrorMessage(e), quoted = "invalid line '";
            const auto at = message.find(quoted);
            long line = 0;
            if (at != std::string::npos) {
                line = lineHolding(fileText, message.substr(at + quoted.size(), message.rfind('\'') - at - quoted.size()));
            } else if (const auto* named = dynamic_cast<const po::error_with_option_name*>(&e)) {
                // An unknown key, or one given twice: the line of the (second) one.
                const bool repeated = dynamic_cast<const po::multiple_occurrences*>(&e) != nullptr;
                line = lineOf(fileText, named->get_option_name(), repeated ? 2 : 1);
            }
            throw InputError(*path, line, message);
        }
        c.sourceFile = *path;
        c.sourceText = fileText;
    }
    c.setKeys = fromSet;
    po::notify(vm);
    checkRanges(keys.table, vm, fromSet, path, fileText);
    const auto refuse = [&](const std::string& key, const std::string& what) { return keyError(key, what, fromSet, path, fileText); };
    try {
        c.block.shape = parseBlockShape(shape);
    } catch (const InputError& e) {
        throw refuse("block.shape", std::string("block.shape: ") + e.what());
    }
    if (orientation != "random" && orientation != "fixed")
        throw refuse("release.orientation", "release.orientation must be random or fixed, not '" + orientation + "'");
    c.release.randomOrientation = orientation == "random";
    c.launch.enabled = vm.count("block.speed_m_s") > 0;
    c.tree.enabled = vm.count("tree.dbh_cm") > 0;
    if (c.launch.enabled && !c.tree.enabled) throw refuse("block.speed_m_s", "block.speed_m_s launches the block at a tree: set tree.dbh_cm too");
    if (reading != "isotropic" && reading != "per_axis")
        throw refuse("stem.bending_reading", "stem.bending_reading must be isotropic or per_axis, not '" + reading + "'");
    c.stem.bending.reading = reading == "isotropic" ? BendingReading::Isotropic : BendingReading::PerAxis;
    if (damping != "viscous" && damping != "constant_loss")
        throw refuse("stem.damping", "stem.damping must be viscous or constant_loss, not '" + damping + "'");
    c.stem.bending.damping = damping == "viscous" ? StemDamping::Viscous : StemDamping::ConstantLoss;
    if (anchorage != "fixed" && anchorage != "stem_weight")
        throw refuse("stem.anchorage", "stem.anchorage must be fixed or stem_weight, not '" + anchorage + "'");
    c.stem.root.anchorage = anchorage == "fixed" ? RootAnchorage::Fixed : RootAnchorage::StemWeight;
    if (treeReach != "block" && treeReach != "centre")
        throw refuse("lumped.tree_reach", "lumped.tree_reach must be block or centre, not '" + treeReach + "'");
    c.lumped.treeReach = treeReach == "block" ? TreeReach::Block : TreeReach::Centre;
    c.stem.root.failureRotation = keys.rootFailureDeg * std::acos(-1.0) / 180;
    // A key the scene's other choices leave unread is refused, not ignored: stem.tau_s under wood's
    // loss factor would change nothing, and the tree would look insensitive to it. A key read from
    // the file is let pass when --set changed the choice it belonged to (the file's keys go with its
    // choices).
    const auto requireRead = [&](const std::string& key, bool read, std::initializer_list<const char*> choices,
                                 const std::string& why) {
        const auto it = vm.find(key);
        if (read || it == vm.end() || it->second.defaulted()) return;
        if (!fromSet.count(key) && std::any_of(choices.begin(), choices.end(), [&](const char* k) { return fromSet.count(k) > 0; })) return;
        throw refuse(key, key + " is not read here: " + why);
    };
    const std::string shapeName = toString(c.block.shape);
    requireRead("block.d1_m", c.block.shape != BlockShapeKind::Sphere, {"block.shape"},
                "a sphere's size is block.volume_m3");
    for (const char* edge : {"block.d2_m", "block.d3_m"})
        requireRead(edge, c.block.shape == BlockShapeKind::Cuboid, {"block.shape"},
                    "a " + shapeName + "'s size is block.volume_m3" + (c.block.shape == BlockShapeKind::Cube ? " or its edge block.d1_m" : "") +
                        "; three edges make a block.shape = cuboid");
    requireRead("block.volume_m3", c.block.shape != BlockShapeKind::Cuboid, {"block.shape"},
                "a cuboid's volume is block.d1_m x d2_m x d3_m");
    // A cube's edge replaced its volume without a word (d1_m = 2 beside volume_m3 = 0.5: 8 m3); a file's
    // volume gives way to an edge typed on --set.
    const double edgeVolume = c.block.d1 * c.block.d1 * c.block.d1;
    requireRead("block.volume_m3",
                c.block.shape != BlockShapeKind::Cube || !vm.count("block.d1_m") || std::abs(c.block.volumeM3 - edgeVolume) <= 1e-9 * edgeVolume,
                {"block.d1_m"},
                "block.d1_m = " + text(c.block.d1) + " sets the cube's size too (" + text(edgeVolume) + " m3); give one of the two");
    const std::string dampingSource = "stem.damping = " + damping + (vm["stem.damping"].defaulted() ? " (stem.parameters = " + c.stemParameters + ")" : "");
    requireRead("stem.tau_s", c.stem.bending.damping == StemDamping::Viscous, {"stem.damping", "stem.parameters"},
                "it is the viscous damping's (Eqs. 7-8), and " + dampingSource + "; set stem.damping = viscous with it");
    requireRead("stem.loss_factor", c.stem.bending.damping == StemDamping::ConstantLoss, {"stem.damping", "stem.parameters"},
                "it is the constant-loss damping's, and " + dampingSource + "; set stem.damping = constant_loss with it");
    requireRead("stem.root_turning_moment_nm_per_kg", c.stem.root.anchorage == RootAnchorage::StemWeight,
                {"stem.anchorage", "stem.parameters"},
                "C_reg sets M_a under stem.anchorage = stem_weight, and this scene's anchorage is fixed (M_a is "
                "stem.root_yield_moment_nm)");
    requireRead("soil.damping_ratio", !vm.count("soil.restitution"), {"soil.restitution"},
                "soil.restitution is given too and sets the damping; give one of the two");
    // The calibrated set's metre of foot zone, under a node spacing coarser than it, becomes the lowest
    // connection cut in two: refusing a scene for a key it never set would teach nothing. A zone the
    // scene set is refused here, with its key and line, rather than by the stem's own check.
    if (c.stem.footZone > 0 && c.stem.footZone < c.stem.nodeSpacing) {
        if (!vm["stem.foot_zone_m"].defaulted())
            throw refuse("stem.foot_zone_m", "stem.foot_zone_m = " + text(c.stem.footZone) + " m is shorter than stem.node_spacing_m = " +
                                                 text(c.stem.nodeSpacing) + " m: give 0 (no zone) or at least the node spacing");
        c.stem.footZone = c.stem.nodeSpacing;
    }
    validate(c.stem);
    c.release.yRangeGiven = vm.count("release.y_min_m") || vm.count("release.y_max_m");
    if (!vm.count("release.y_min_m")) c.release.yMin = c.release.y;
    if (!vm.count("release.y_max_m")) c.release.yMax = c.release.y;
    // Two keys in one refusal: the one typed on --set is named, else the file's line of either.
    const auto givenOf = [&](std::initializer_list<const char*> pair) {
        for (const char* k : pair)
            if (fromSet.count(k)) return k;
        for (const char* k : pair)
            if (vm.count(k) && !vm[k].defaulted()) return k;
        return *pair.begin();
    };
    if (c.release.yMax < c.release.yMin) {
        const std::string blamed = givenOf({"release.y_max_m", "release.y_min_m"});
        throw refuse(blamed, blamed == "release.y_max_m"
                                 ? "release.y_max_m = " + text(c.release.yMax) + " is below release.y_min_m = " + text(c.release.yMin)
                                 : "release.y_min_m = " + text(c.release.yMin) + " is above release.y_max_m = " + text(c.release.yMax));
    }
    if (vm.count("soil.restitution")) c.soilContact.dampingRatio = dampingRatioFromRestitution(keys.restitution);
    if (c.block.shape == BlockShapeKind::Cube && vm.count("block.d1_m")) c.block.volumeM3 = edgeVolume;
    // The clump's spheres have a quarter of the shortest edge (Eq. 1), so their number grows with the
    // square of the edges' ratio: 20 x 20 x 0.001 m would take 2e10 spheres. A ratio of 10 still
    // allows 4 600 spheres (a cube has 27); a limit of cost, not a measured bound on rock shapes.
    if (c.block.shape == BlockShapeKind::Cuboid && c.block.d1 > 0 && c.block.d2 > 0 && c.block.d3 > 0) {
        const double ratio = std::max({c.block.d1, c.block.d2, c.block.d3}) / std::min({c.block.d1, c.block.d2, c.block.d3});
        if (ratio > 10)
            throw refuse(givenOf({"block.d3_m", "block.d2_m", "block.d1_m"}), "block.d1_m, d2_m, d3_m: the longest edge is " + text(ratio) +
                                 " times the shortest, above 10 (the clump's spheres are a quarter of the shortest edge, "
                                 "Eq. 1, so their number grows with the ratio squared): a slab that thin is not a block");
    }
    // The soil's random rows are drawn by a generator that keeps 32 bits of its seed: 2^32 + 1 would
    // draw seed 1's bed, and -1, read as 2^64 - 1, seed 2^32 - 1's.
    if (c.terrain.soil.seed > 0xFFFFFFFFull)
        throw refuse("terrain.seed", "terrain.seed = " + std::to_string(c.terrain.soil.seed) +
                             " is outside 0 to 4294967295 (the generator keeps 32 bits; a negative seed reads as a huge one)");
    // Wood crushes across the grain at a few MPa (3.7e6 Pa, docs/model-stems.md, "Crushing"): a value
    // in Pa this small is one in MPa, and would let the block crush through any stem.
    if (c.stemContact.crushingStrength > 0 && c.stemContact.crushingStrength < 1e5)
        throw refuse("tree_contact.crushing_strength_pa", "tree_contact.crushing_strength_pa = " + text(c.stemContact.crushingStrength) +
                             " Pa is below 1e5 Pa: MPa typed as Pa? (3.7 MPa is 3.7e6; 0 turns crushing off)");
    if (c.integration.anticipatedContacts < 1 || c.integration.anticipatedContacts > 1000)
        throw refuse("integration.anticipated_contacts", "integration.anticipated_contacts = " + text(c.integration.anticipatedContacts) + ": outside [1, 1000]");
    if (c.lumped.soilType < 0 || c.lumped.soilType > 7)
        throw refuse("lumped.soil_type", "lumped.soil_type = " + text(c.lumped.soilType) + ": Rockyfor3D soil types are 0 to 7 (docs/lumped.md)");
    // Terrain paths are relative to the scene file.
    if (path) {
        const auto dir = std::filesystem::path(*path).parent_path();
        for (std::string* p : {&c.terrain.profile, &c.terrain.dtm, &c.forestFile})
            if (!p->empty() && std::filesystem::path(*p).is_relative()) *p = (dir / *p).lexically_normal().string();
    }
    return c;
}

}  // namespace

InputError SceneConfig::refusal(const std::vector<const char*>& keys, const std::string& what) const {
    // --set first: what the user changed last is the likelier cause (a launch distance set too long
    // names that, not the tree's position in the file).
    for (const char* key : keys)
        if (setKeys.count(key)) return InputError("--set " + std::string(key) + ": " + what);
    for (const char* key : keys)
        if (const long line = lineOf(sourceText, key)) return InputError(sourceFile, line, what);
    return InputError(sourceFile, 0, what);
}

SceneConfig loadScene(const std::string& path, const std::vector<std::string>& overrides) { return load(&path, overrides); }

SceneConfig sceneFromOverrides(const std::vector<std::string>& overrides) { return load(nullptr, overrides); }

std::string describeSceneKeys() {
    const SceneKeys keys;
    std::ostringstream os;
    os << keys.table.keys();
    return os.str();
}

std::vector<std::string> sceneNumberKeys() {
    const SceneKeys keys;
    std::vector<std::string> names;
    for (const NumericKey& n : keys.table.numbers()) names.push_back(n.name);
    return names;
}

}  // namespace sylva::dem
