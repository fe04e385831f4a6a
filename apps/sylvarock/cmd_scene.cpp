// sylvarock scene export: the scene's spheres and stems as plain files another DEM code or ParaView can load.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <iomanip>
#include <iostream>
#include <vector>

#include "Cli.hpp"
#include "libdem/BlockMotion.hpp"
#include "libdem/Campaign.hpp"
#include "libdem/SoilContact.hpp"
#include "libdem/Stem.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::cli {
namespace {

struct StemCount {
    std::size_t stems = 0, nodes = 0;
};

// Every stem at rest, built as the simulator builds it when the block wakes it (ForestMotion::wake),
// one row per node. A forest of 20 000 stems gives ~600 000 rows: one buffered stream, and each
// Stem is dropped once written.
StemCount writeStemsCsv(const std::string& path, const dem::Scene& scene) {
    std::vector<char> buffer(1 << 20);
    std::ofstream out;
    out.rdbuf()->pubsetbuf(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    out.open(path);
    if (!out) throw cannotWrite(path);
    out << std::setprecision(9) << "tree,node,x,y,z,radius,linked_to,dbh_cm,stool\n";
    StemCount count;
    const dem::TreeField& trees = scene.trees();
    for (std::size_t i = 0; i < trees.size(); ++i) {
        const dem::PlacedTree& t = trees.tree(i);
        const auto& stool = scene.forest().trees[i].stool;  // TreeField keeps the forest's order
        const dem::Stem stem(t.geometry, scene.config().stem, t.foot, t.support);
        for (std::size_t k = 0; k < stem.nodeCount(); ++k) {
            const dem::Vec3& p = stem.position[k];
            out << t.id << ',' << k << ',' << p.x() << ',' << p.y() << ',' << p.z() << ','
                << stem.nodeRadius(k) << ',' << static_cast<long>(k) - 1 << ','
                << 100 * t.geometry.dbh << ',';
            if (stool) out << *stool;
            out << '\n';
        }
        ++count.stems;
        count.nodes += stem.nodeCount();
    }
    out.flush();
    if (!out) throw InputError(path, 0, "write failed (disk full?)");
    return count;
}

// What another DEM code needs to start the same run and end it where simulate does (BlockRun: the
// block leaves the soil bed's extent).
void writeRelease(const std::string& path, const dem::Scene& scene, const dem::Release& release) {
    std::ofstream rel(path);
    if (!rel) throw cannotWrite(path);
    const dem::RigidBody& block = scene.blockTemplate();
    const auto& q = release.orientation;
    const dem::Vec3& p = release.position;
    const dem::Vec3& inertia = block.principalInertia();
    const dem::SoilBed& soil = scene.soil();
    // The velocity is a single-tree launch's (block.speed_m_s), zero for a release from rest: without
    // it another code dropped the launched block from rest.
    const dem::Vec3& v = release.velocity;
    rel << std::setprecision(12) << "x,y,z,qw,qx,qy,qz,mass_kg,ixx_kg_m2,iyy_kg_m2,izz_kg_m2,xmin,xmax,ymin,ymax,vx_m_s,vy_m_s,vz_m_s\n"
        << p.x() << ',' << p.y() << ',' << p.z() << ',' << q.w() << ',' << q.x() << ',' << q.y() << ',' << q.z() << ','
        << block.mass() << ',' << inertia.x() << ',' << inertia.y() << ',' << inertia.z() << ',' << soil.xmin() << ','
        << soil.xmax() << ',' << soil.ymin() << ',' << soil.ymax() << ',' << v.x() << ',' << v.y() << ',' << v.z() << '\n';
    rel.close();  // a small file fails only when its buffer is written
    if (!rel) throw InputError(path, 0, "write failed (disk full?)");
}

void writeSoilContact(const std::string& path, const dem::Scene& scene) {
    const dem::SoilContactParams& p = scene.config().soilContact;
    const dem::SoilContact law(p, scene.blockTemplate().mass());  // the block/soil law simulate builds (Scene)
    std::ofstream out(path);
    if (!out) throw cannotWrite(path);
    out << std::setprecision(12) << "kn_n_m,kt_n_m,damping_n_s,friction_deg,normal_force_floored,gravity_m_s2\n"
        << p.kn << ',' << law.tangentialStiffness() << ',' << law.dampingCoefficient() << ',' << p.frictionDeg << ','
        << (p.dashpotPulls ? 0 : 1) << ',' << scene.config().gravity << '\n';
    out.close();
    if (!out) throw InputError(path, 0, "write failed (disk full?)");
}

// The block's spheres in its body frame.
void writeBlockSpheres(const std::string& path, const dem::RigidBody& block) {
    std::ofstream out(path);
    if (!out) throw cannotWrite(path);
    out << std::setprecision(12) << "x,y,z,r\n";
    for (const auto& s : block.spheres()) out << s.offset.x() << ',' << s.offset.y() << ',' << s.offset.z() << ',' << s.radius << '\n';
    out.close();
    if (!out) throw InputError(path, 0, "write failed (disk full?)");
}

int runScene(int argc, const char* const* argv) {
    po::options_description o("scene");
    std::vector<std::string> sets;
    o.add_options()("action", po::value<std::string>(), "export")("scene", po::value<std::string>(), "scene INI file")(
        "forest", po::value<std::string>(), kForestHelp)(
        "seed", po::value<Seed>()->default_value(Seed{}, "1"), "campaign seed")(
        "run", po::value<long>()->default_value(0), "the run of the campaign whose release is written (0, 1, ...)")(
        "out", po::value<std::string>(), "output directory")(
        "set", po::value(&sets)->composing(), "override a scene key: --set section.key=value");
    po::variables_map vm;
    // The action is positional: sylvarock scene export ...
    std::vector<const char*> args(argv, argv + argc);
    if (argc > 1 && argv[1][0] != '-') {
        if (std::string(argv[1]) != "export") throw InputError("unknown scene action '" + std::string(argv[1]) + "' (try: export)");
        args.erase(args.begin() + 1);
    }
    if (!parse(static_cast<int>(args.size()), args.data(), o, vm,
               "sylvarock scene export --scene FILE.ini [--forest F.csv] [--seed S] --out DIR",
               "  sylvarock scene export --scene data/scenes/no-forest.ini --forest forest.csv --out out/scene\n"
               "  sylvarock scene export --scene data/scenes/single-tree.ini --set tree.dbh_cm=30 --out out/tree\n"
               "  sylvarock scene export --scene data/scenes/no-forest.ini --seed 4 --run 7 --out out/run7\n"
               "writes soil_spheres.csv (x,y,z,r), block_spheres.csv (body frame: x,y,z,r), release.csv (the\n"
               "block's centre, orientation, velocity, mass and principal inertia at the release of run --run of campaign\n"
               "--seed, and the domain it stops on leaving), soil_contact.csv (Eqs. 14-19: K_n, K_t, alpha,\n"
               "phi, gravity; the block/soil law as simulate applies it, for another DEM code) and\n"
               "stems.csv: every stem of the forest (forest.file or --forest) or of the single tree (tree.* keys)\n"
               "at rest, one row per node from the foot (node 0) up: tree,node,x,y,z,radius (m),\n"
               "linked_to (the node below, -1 at the foot),dbh_cm,stool (empty for a stem on its own roots)\n"))
        return 0;
    if (vm.count("action") && vm["action"].as<std::string>() != "export")
        throw InputError("unknown scene action '" + vm["action"].as<std::string>() + "' (try: export)");
    if (!vm.count("scene") || !vm.count("out")) throw InputError("--scene and --out are required");
    applyForestOption(vm, sets);
    const std::string out = vm["out"].as<std::string>();
    const long run = vm["run"].as<long>();
    // A campaign's runs are numbered by an int (--runs): a larger number would wrap to another run's release.
    if (run < 0 || run > std::numeric_limits<int>::max())
        throw InputError("--run " + std::to_string(run) + " is not a run of a campaign (0 to " +
                         std::to_string(std::numeric_limits<int>::max()) + ")");
    if (std::filesystem::exists(out) && !std::filesystem::is_directory(out)) throw InputError("--out " + out + " is a file, not a folder");
    const dem::Scene scene(dem::loadScene(vm["scene"].as<std::string>(), sets));
    // Every input error before the first file: a refused release left the soil and block files written.
    const dem::Release release = dem::drawRelease(scene, dem::runSeed(vm["seed"].as<Seed>().value, run));
    // The start simulate refuses (the block inside the soil or a stem, a soil too soft to hold it) is
    // refused here too: the files would hand another code a run that cannot be made.
    const dem::BlockMotion start(scene, release);
    std::filesystem::create_directories(out);
    scene.soil().writeCsv(out + "/soil_spheres.csv");
    writeBlockSpheres(out + "/block_spheres.csv", scene.blockTemplate());
    writeRelease(out + "/release.csv", scene, release);
    writeSoilContact(out + "/soil_contact.csv", scene);
    const StemCount stems = writeStemsCsv(out + "/stems.csv", scene);
    std::printf("%zu soil spheres, %zu block spheres, %zu stems (%zu stem nodes) written to %s/\n", scene.soil().size(),
                scene.blockTemplate().spheres().size(), stems.stems, stems.nodes, out.c_str());
    return 0;
}

const CommandRegistration reg{{7, "scene", "export a scene's spheres (soil, block) and stems for ParaView or another DEM code", &runScene}};

}  // namespace
}  // namespace sylva::cli
