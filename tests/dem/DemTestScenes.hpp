#pragma once
// Small scenes for the libdem tests: a straight slope written to a temporary profile file.
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "../WholeFile.hpp"
#include "libdem/Scene.hpp"

namespace sylva::dem::testing {

// A straight profile falling at `slopeDeg` over `length` m (x from 0), at a path fixed by its name.
inline std::string straightProfile(const std::string& name, double slopeDeg, double length) {
    const auto dir = std::filesystem::temp_directory_path() / "sylvarock-tests";
    std::filesystem::create_directories(dir);
    std::ostringstream text;
    text << "x,z\n0," << length * std::tan(slopeDeg * M_PI / 180) << "\n" << length << ",0\n";
    return sylva::testfiles::writeWholeFile(dir / (name + ".csv"), text.str());
}

// Scene keys for a straight slope; extra overrides are appended (and win over none here).
inline SceneConfig straightSlopeScene(double slopeDeg, double length, double width, std::vector<std::string> extra = {}) {
    std::vector<std::string> keys = {
        "terrain.profile=" + straightProfile("slope" + std::to_string(slopeDeg) + "_" + std::to_string(length), slopeDeg, length),
        "terrain.width_m=" + std::to_string(width)};
    keys.insert(keys.begin(), extra.begin(), extra.end());  // --set semantics: the first value stored wins
    return sceneFromOverrides(keys);
}

}  // namespace sylva::dem::testing
