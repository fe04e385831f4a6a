// sylvarock scene export: the scene's spheres and stems as plain files another DEM code or ParaView can load.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <vector>

#include "Cli.hpp"
#include "libdem/Campaign.hpp"
#include "libdem/Stem.hpp"
#include "libstand/InputError.hpp"

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
    if (!out) throw InputError(path, 0, "cannot open file for writing");
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
                << 0.5 * stem.diameterAt(stem.restHeight(k)) << ',' << static_cast<long>(k) - 1 << ','
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

int runScene(int argc, const char* const* argv) {
    po::options_description o("scene");
    std::vector<std::string> sets;
    o.add_options()("action", po::value<std::string>(), "export")("scene", po::value<std::string>(), "scene INI file")(
        "forest", po::value<std::string>(), kForestHelp)(
        "seed", po::value<unsigned long>()->default_value(1), "campaign seed: the release written is run 0's")(
        "out", po::value<std::string>(), "output directory")(
        "set", po::value(&sets)->composing(), "override a scene key: --set section.key=value");
    po::positional_options_description pos;
    pos.add("action", 1);
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
               "writes soil_spheres.csv (x,y,z,r), block_spheres.csv (body frame: x,y,z,r), release.csv and\n"
               "stems.csv: every stem of the forest (forest.file or --forest) or of the single tree (tree.* keys)\n"
               "at rest, one row per node from the foot (node 0) up: tree,node,x,y,z,radius (m),\n"
               "linked_to (the node below, -1 at the foot),dbh_cm,stool (empty for a stem on its own roots)\n"))
        return 0;
    if (!vm.count("scene") || !vm.count("out")) throw InputError("--scene and --out are required");
    applyForestOption(vm, sets);
    const std::string out = vm["out"].as<std::string>();
    const dem::Scene scene(dem::loadScene(vm["scene"].as<std::string>(), sets));
    std::filesystem::create_directories(out);
    scene.soil().writeCsv(out + "/soil_spheres.csv");
    std::ofstream block(out + "/block_spheres.csv");
    block << "x,y,z,r\n";
    for (const auto& s : scene.blockTemplate().spheres())
        block << s.offset.x() << ',' << s.offset.y() << ',' << s.offset.z() << ',' << s.radius << '\n';
    const auto first = dem::drawRelease(scene, dem::runSeed(vm["seed"].as<unsigned long>(), 0));
    const auto& q = first.orientation;
    std::ofstream rel(out + "/release.csv");
    rel << "x,y,z,qw,qx,qy,qz,mass_kg\n" << first.position.x() << ',' << first.position.y() << ',' << first.position.z()
        << ',' << q.w() << ',' << q.x() << ',' << q.y() << ',' << q.z() << ',' << scene.blockTemplate().mass() << '\n';
    const StemCount stems = writeStemsCsv(out + "/stems.csv", scene);
    std::printf("%zu soil spheres, %zu block spheres, %zu stems (%zu stem nodes) written to %s/\n", scene.soil().size(),
                scene.blockTemplate().spheres().size(), stems.stems, stems.nodes, out.c_str());
    return 0;
}

const CommandRegistration reg{{"scene", "export a scene's spheres (soil, block) and stems for ParaView or another DEM code", &runScene}};

}  // namespace
}  // namespace sylva::cli
