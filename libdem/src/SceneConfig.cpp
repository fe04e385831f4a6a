#include "libdem/SceneConfig.hpp"

#include <boost/program_options.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "libstand/InputError.hpp"

namespace sylva::dem {

namespace po = boost::program_options;

namespace {

template <class T>
std::string text(const T& v) {
    std::ostringstream os;
    os << v;  // shortest readable form (0.7, not 0.69999999999999996)
    return os.str();
}

// One table of keys: name, target, default, meaning. The INI sections are the part before the dot.
po::options_description sceneKeys(SceneConfig& c, std::string& shape, std::string& orientation, double& restitution,
                                  std::string& reading) {
    po::options_description d("Scene keys ([section] key = value, or --set section.key=value)");
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
    d.add_options()
        ("terrain.profile", po::value(&t.profile), "slope profile CSV with columns x,z (m), relative to the scene file")
        ("terrain.dtm", po::value(&t.dtm), "or a DTM as an ESRI ASCII grid (.asc)")
        ("forest.file", po::value(&c.forestFile), "forest CSV (from sylvarock generate, or x,y,dbh_cm[,stool]); relative to the scene file")
        ("terrain.width_m", po::value(&t.soil.width)->default_value(t.soil.width, text(t.soil.width)), "extent across the slope of a profile terrain, m")
        ("terrain.soil_radius_m", po::value(&t.soil.radius)->default_value(t.soil.radius, text(t.soil.radius)), "R_soil, m (Table 2: 0.7)")
        ("terrain.roughness_m", po::value(&t.soil.roughness)->default_value(t.soil.roughness, text(t.soil.roughness)), "bump height between soil spheres, m (Table 2: 0.1)")
        ("terrain.seed", po::value(&t.soil.seed)->default_value(t.soil.seed, text(t.soil.seed)), "seed of the rows' offsets across the slope (Fig. 7)")
        ("soil.kn_n_m", po::value(&s.kn)->default_value(s.kn, text(s.kn)), "K_n^soil, N/m (Table 2)")
        ("soil.kappa", po::value(&s.kappa)->default_value(s.kappa, text(s.kappa)), "K_t/K_n (Eq. 19)")
        ("soil.damping_ratio", po::value(&s.dampingRatio)->default_value(s.dampingRatio, text(s.dampingRatio)), "alpha/alpha_cr (Eq. 15)")
        ("soil.restitution", po::value(&restitution), "e_n instead of damping_ratio (Eq. 15)")
        ("soil.dashpot_pulls", po::value(&s.dashpotPulls)->default_value(s.dashpotPulls, text(s.dashpotPulls)), "Eq. 14 as written (true: the dashpot may pull at the end of a rebound) or floored at zero (false, as Yade)")
        ("soil.friction_deg", po::value(&s.frictionDeg)->default_value(s.frictionDeg, text(s.frictionDeg)), "phi^soil, degrees")
        ("block.shape", po::value(&shape)->default_value(shape, text(shape)), "cube | cuboid | sphere")
        ("block.volume_m3", po::value(&b.volumeM3)->default_value(b.volumeM3, text(b.volumeM3)), "volume of a cube or sphere block, m^3")
        ("block.d1_m", po::value(&b.d1), "cuboid edge 1, m")
        ("block.d2_m", po::value(&b.d2), "cuboid edge 2, m")
        ("block.d3_m", po::value(&b.d3), "cuboid edge 3, m")
        ("block.density_kg_m3", po::value(&b.densityKgM3)->default_value(b.densityKgM3, text(b.densityKgM3)), "kg/m^3 (Table 2: 2700)")
        ("release.x_m", po::value(&r.x)->default_value(r.x, text(r.x)), "release x, m")
        ("release.y_m", po::value(&r.y)->default_value(r.y, text(r.y)), "release y, m (runs without forest)")
        ("release.y_min_m", po::value(&r.yMin), "release y drawn uniformly in [y_min_m, y_max_m]")
        ("release.y_max_m", po::value(&r.yMax), "")
        ("release.forest_y_min_m", po::value(&r.forestYMin)->default_value(r.forestYMin, text(r.forestYMin)), "with a forest and no y range: y uniform in [forest_y_min_m, forest_y_max_m] (Sect. 2.3.2)")
        ("release.forest_y_max_m", po::value(&r.forestYMax)->default_value(r.forestYMax, text(r.forestYMax)), "")
        ("release.fall_height_m", po::value(&r.fallHeight)->default_value(r.fallHeight, text(r.fallHeight)), "block centre above the surface, m")
        ("release.orientation", po::value(&orientation)->default_value(orientation, text(orientation)), "random (angles in [0,180) deg about x,y,z) | fixed")
        ("block.speed_m_s", po::value(&c.launch.speed), "single-tree scenes: launch the block at this speed toward the tree (+x)")
        ("block.impact_height_m", po::value(&c.launch.impactHeight)->default_value(c.launch.impactHeight, text(c.launch.impactHeight)), "... its centre this high above the stem's foot")
        ("block.eccentricity", po::value(&c.launch.eccentricity)->default_value(c.launch.eccentricity, text(c.launch.eccentricity)), "... offset across its path by this fraction of (block radius + stem radius), in [-1, 1]")
        ("block.launch_distance_m", po::value(&c.launch.distance)->default_value(c.launch.distance, text(c.launch.distance)), "... starting this far before the stem's axis")
        ("tree.dbh_cm", po::value(&c.tree.dbhCm), "single-tree scenes: one tree of this DBH (replaces forest.file)")
        ("tree.x_m", po::value(&c.tree.x)->default_value(c.tree.x, text(c.tree.x)), "its position, m")
        ("tree.y_m", po::value(&c.tree.y)->default_value(c.tree.y, text(c.tree.y)), "")
        ("tree.coppice", po::value(&c.tree.coppice)->default_value(c.tree.coppice, text(c.tree.coppice)), "a coppice stem (clamped foot) instead of a single tree (root spring)")
        ("integration.safety", po::value(&i.safety)->default_value(i.safety, text(i.safety)), "time step as a fraction of the stable limit")
        ("integration.stem_safety", po::value(&i.stemSafety)->default_value(i.stemSafety, text(i.stemSafety)), "time step as a fraction of the awake stems' stable limit")
        ("integration.dt_s", po::value(&i.forcedDt)->default_value(i.forcedDt, text(i.forcedDt)), "force this time step (0: automatic); refused if unstable")
        ("integration.anticipated_contacts", po::value(&i.anticipatedContacts)->default_value(i.anticipatedContacts, text(i.anticipatedContacts)), "new contacts the step must stay stable for")
        ("integration.energy_tolerance", po::value(&i.energyTolerance)->default_value(i.energyTolerance, text(i.energyTolerance)), "relative energy growth that stops a run")
        ("integration.energy_warning", po::value(&i.energyWarning)->default_value(i.energyWarning, text(i.energyWarning)), "relative energy imbalance above which a run is flagged (runs.csv energy_flag, summary.json energy_flagged_runs)")
        ("stop.rest_distance_m", po::value(&st.restDistance)->default_value(st.restDistance, text(st.restDistance)), "the block rests once its centre stays within this distance of one point ...")
        ("stop.rest_time_s", po::value(&st.restTime)->default_value(st.restTime, text(st.restTime)), "... for this long, s")
        ("stop.max_time_s", po::value(&st.maxTime)->default_value(st.maxTime, text(st.maxTime)), "simulated time limit, s")
        ("stem.node_spacing_m", po::value(&stem.nodeSpacing)->default_value(stem.nodeSpacing, text(stem.nodeSpacing)), "largest distance between a stem's nodes, m")
        ("stem.tip_diameter_m", po::value(&stem.tipDiameter)->default_value(stem.tipDiameter, text(stem.tipDiameter)), "diameter of the cone at H_T, m")
        ("stem.density_kg_m3", po::value(&stem.density)->default_value(stem.density, text(stem.density)), "fresh wood (Table 2: 1.2 t/m^3)")
        ("stem.poisson", po::value(&stem.poisson)->default_value(stem.poisson, text(stem.poisson)), "nu, for shear and twist (not in the paper)")
        ("stem.moe_pa", po::value(&bend.moe)->default_value(bend.moe, text(bend.moe)), "MOE (Eq. 2)")
        ("stem.e_plast_pa", po::value(&bend.ePlast)->default_value(bend.ePlast, text(bend.ePlast)), "E_Plast (Eq. 3)")
        ("stem.e_unld_pa", po::value(&bend.eUnld)->default_value(bend.eUnld, text(bend.eUnld)), "E_Unld (Eq. 4)")
        ("stem.sigma_elast_pa", po::value(&bend.sigmaElast)->default_value(bend.sigmaElast, text(bend.sigmaElast)), "sigma_Elast (Eq. 5)")
        ("stem.sigma_rupt_pa", po::value(&bend.sigmaRupt)->default_value(bend.sigmaRupt, text(bend.sigmaRupt)), "sigma_Rupt (Eq. 6)")
        ("stem.sections", po::value(&bend.sections)->default_value(bend.sections, text(bend.sections)), "sections per connection where Fig. 3 acts: 1 (the paper: at the connection's middle) | 3 | 5 (along the connection, where the moment changes; docs/model-stems.md)")
        ("stem.tau_s", po::value(&bend.tau)->default_value(bend.tau, text(bend.tau)), "tau (Eqs. 7-8)")
        ("stem.bending_reading", po::value(&reading)->default_value(reading), "isotropic (moment vector) | per_axis (the paper's x and y laws)")
        ("stem.root_stiffness_nm_rad", po::value(&stem.root.stiffness)->default_value(stem.root.stiffness, text(stem.root.stiffness)), "K_Root (Eqs. 9-10)")
        ("stem.root_yield_moment_nm", po::value(&stem.root.yieldMoment)->default_value(stem.root.yieldMoment, text(stem.root.yieldMoment)), "M_a")
        ("tree_contact.er_pa", po::value(&tc.woodRadialModulus)->default_value(tc.woodRadialModulus, text(tc.woodRadialModulus)), "E_r (Eqs. 22-23)")
        ("tree_contact.eb_pa", po::value(&tc.blockModulus)->default_value(tc.blockModulus, text(tc.blockModulus)), "E_b (Eq. 22)")
        ("tree_contact.kappa_block_stem", po::value(&tc.kappaBlockStem)->default_value(tc.kappaBlockStem, text(tc.kappaBlockStem)), "kappa_b-t")
        ("tree_contact.friction_block_stem_deg", po::value(&tc.frictionBlockStemDeg)->default_value(tc.frictionBlockStemDeg, text(tc.frictionBlockStemDeg)), "phi_b-t")
        ("tree_contact.kappa_stem_stem", po::value(&tc.kappaStemStem)->default_value(tc.kappaStemStem, text(tc.kappaStemStem)), "kappa_t-t")
        ("tree_contact.friction_stem_stem_deg", po::value(&tc.frictionStemStemDeg)->default_value(tc.frictionStemStemDeg, text(tc.frictionStemStemDeg)), "phi_t-t")
        ("forest.wake_margin_m", po::value(&act.wakeMargin)->default_value(act.wakeMargin, text(act.wakeMargin)), "a stem is built when the block comes this close, m")
        ("forest.sleep_after_s", po::value(&act.sleepAfter)->default_value(act.sleepAfter, text(act.sleepAfter)), "a stem sleeps after this long without the block, s")
        ("forest.all_awake", po::value(&act.allAwake)->default_value(act.allAwake, text(act.allAwake)), "reference mode: every stem awake from the start")
        ("gravity_m_s2", po::value(&c.gravity)->default_value(c.gravity, text(c.gravity)), "")
        ("output.trajectory_interval_s", po::value(&c.trajectoryInterval)->default_value(c.trajectoryInterval, text(c.trajectoryInterval)), "trajectory sampling, s");
    return d;
}

std::string overridesAsIni(const std::vector<std::string>& overrides) {
    std::string ini;
    for (const auto& o : overrides) {
        const auto eq = o.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError("--set '" + o + "': expected section.key=value");
        const std::string key = o.substr(0, eq);
        const auto dot = key.rfind('.');
        if (dot == std::string::npos) ini += key + "=" + o.substr(eq + 1) + "\n";
        else ini += "[" + key.substr(0, dot) + "]\n" + key.substr(dot + 1) + "=" + o.substr(eq + 1) + "\n";
    }
    return ini;
}

SceneConfig load(const std::string* path, const std::vector<std::string>& overrides) {
    SceneConfig c;
    std::string shape = "cube", orientation = "random", reading = "isotropic";
    double restitution = -1;
    po::options_description d = sceneKeys(c, shape, orientation, restitution, reading);
    po::variables_map vm;
    std::istringstream setIni(overridesAsIni(overrides));
    try {
        po::store(po::parse_config_file(setIni, d), vm);  // first stored wins: --set over the file
    } catch (const po::error& e) {
        throw InputError(std::string("--set: ") + e.what());
    }
    if (path) {
        std::ifstream in(*path);
        if (!in) throw InputError(*path, 0, "cannot open scene file");
        try {
            po::store(po::parse_config_file(in, d), vm);
        } catch (const po::error& e) {
            throw InputError(*path, 0, e.what());
        }
        c.sourceFile = *path;
    }
    po::notify(vm);
    c.block.shape = parseBlockShape(shape);
    if (orientation != "random" && orientation != "fixed")
        throw InputError("release.orientation must be random or fixed, not '" + orientation + "'");
    c.release.randomOrientation = orientation == "random";
    c.launch.enabled = vm.count("block.speed_m_s") > 0;
    c.tree.enabled = vm.count("tree.dbh_cm") > 0;
    if (c.launch.enabled && !c.tree.enabled) throw InputError("block.speed_m_s launches the block at a tree: set tree.dbh_cm too");
    if (c.tree.enabled && !(c.tree.dbhCm > 0)) throw InputError("tree.dbh_cm must be positive");
    if (c.launch.enabled && !(std::abs(c.launch.eccentricity) <= 1)) throw InputError("block.eccentricity must be in [-1, 1]");
    if (reading != "isotropic" && reading != "per_axis")
        throw InputError("stem.bending_reading must be isotropic or per_axis, not '" + reading + "'");
    c.stem.bending.reading = reading == "isotropic" ? BendingReading::Isotropic : BendingReading::PerAxis;
    validate(c.stem);
    c.release.yRangeGiven = vm.count("release.y_min_m") || vm.count("release.y_max_m");
    if (!vm.count("release.y_min_m")) c.release.yMin = c.release.y;
    if (!vm.count("release.y_max_m")) c.release.yMax = c.release.y;
    if (c.release.yMax < c.release.yMin) throw InputError("release.y_max_m is below release.y_min_m");
    if (restitution >= 0) {
        if (!(restitution > 0 && restitution <= 1)) throw InputError("soil.restitution must be in (0, 1]");
        c.soilContact.dampingRatio = dampingRatioFromRestitution(restitution);
    }
    if (c.block.shape == BlockShapeKind::Cube && vm.count("block.d1_m")) c.block.volumeM3 = c.block.d1 * c.block.d1 * c.block.d1;
    if (!(c.integration.safety > 0 && c.integration.safety <= 1) || !(c.integration.stemSafety > 0 && c.integration.stemSafety <= 1))
        throw InputError("integration.safety and integration.stem_safety must be in (0, 1]");
    if (!(c.integration.energyTolerance > 0 && c.integration.energyWarning > 0))
        throw InputError("integration.energy_tolerance and integration.energy_warning must be positive");
    if (!(c.stop.maxTime > 0 && c.stop.restTime > 0 && c.stop.restDistance > 0))
        throw InputError("stop.max_time_s, stop.rest_time_s and stop.rest_distance_m must be positive");
    // Terrain paths are relative to the scene file.
    if (path) {
        const auto dir = std::filesystem::path(*path).parent_path();
        for (std::string* p : {&c.terrain.profile, &c.terrain.dtm, &c.forestFile})
            if (!p->empty() && std::filesystem::path(*p).is_relative()) *p = (dir / *p).lexically_normal().string();
    }
    return c;
}

}  // namespace

SceneConfig loadScene(const std::string& path, const std::vector<std::string>& overrides) { return load(&path, overrides); }

SceneConfig sceneFromOverrides(const std::vector<std::string>& overrides) { return load(nullptr, overrides); }

std::string describeSceneKeys() {
    SceneConfig c;
    std::string shape = "cube", orientation = "random", reading = "isotropic";
    double restitution = -1;
    std::ostringstream os;
    os << sceneKeys(c, shape, orientation, restitution, reading);
    return os.str();
}

}  // namespace sylva::dem
