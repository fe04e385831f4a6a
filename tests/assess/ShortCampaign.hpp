#pragma once
// A small assessment on the short test slope (tests/assess/data/short-scene.ini): stand GR1, a few
// runs, each campaign taking about a second, for the tests of resuming and of the store.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "libassess/Assessment.hpp"

inline sylva::assess::AssessmentOptions shortCampaign(const std::filesystem::path& out, int runs, int realisations, int baselineRuns,
                                                     std::uint64_t seed) {
    sylva::assess::AssessmentOptions o;
    o.design.stands.push_back(sylva::assess::standFromPrefix(std::string(SYLVAROCK_DATA) + "/stands/GR1"));
    o.design.sceneFile = std::string(SYLVAROCK_TEST_DATA) + "/../assess/data/short-scene.ini";
    o.design.runs = runs;
    o.design.realisations = realisations;
    o.design.baselineRuns = baselineRuns;
    o.design.seed = seed;
    o.outDir = out.string();
    return o;
}

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
