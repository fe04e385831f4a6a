// A scene INI file, read and validated key by key (the soil bed is not built: that is the terrain's
// job, fuzzed through the profile and DTM targets). A valid profile sits beside it, so that
// `profile = short-slope.csv` lets the fuzzer past the terrain section.
#include "FuzzFile.hpp"
#include "libdem/SceneConfig.hpp"
#include "libcommon/InputError.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    static const bool profile = [] {
        fuzz::file("short-slope.csv", "x,z\n0,100\n100,42.3\n200,33.5\n");
        return true;
    }();
    (void)profile;
    try {
        dem::loadScene(fuzz::file("scene.ini", fuzz::text(data, size)));
    } catch (const InputError&) {
    }
    return 0;
}
