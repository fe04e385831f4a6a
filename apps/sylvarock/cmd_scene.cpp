// sylvarock scene export: the scene's spheres as plain files another DEM code or ParaView can load.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "Cli.hpp"
#include "libdem/Campaign.hpp"
#include "libstand/InputError.hpp"

namespace sylva::cli {
namespace {

int runScene(int argc, const char* const* argv) {
    po::options_description o("scene");
    std::vector<std::string> sets;
    o.add_options()("action", po::value<std::string>(), "export")("scene", po::value<std::string>(), "scene INI file")(
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
    if (!parse(static_cast<int>(args.size()), args.data(), o, vm, "sylvarock scene export --scene FILE.ini [--seed S] --out DIR",
               "  sylvarock scene export --scene data/scenes/no-forest.ini --out out/scene\n"
               "writes soil_spheres.csv (x,y,z,r), block_spheres.csv (body frame: x,y,z,r) and release.csv\n"))
        return 0;
    if (!vm.count("scene") || !vm.count("out")) throw InputError("--scene and --out are required");
    const std::string out = vm["out"].as<std::string>();
    std::filesystem::create_directories(out);
    const dem::Scene scene(dem::loadScene(vm["scene"].as<std::string>(), sets));
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
    std::printf("%zu soil spheres, %zu block spheres written to %s/\n", scene.soil().size(),
                scene.blockTemplate().spheres().size(), out.c_str());
    return 0;
}

const CommandRegistration reg{{"scene", "export a scene's spheres (soil, block) for ParaView or another DEM code", &runScene}};

}  // namespace
}  // namespace sylva::cli
