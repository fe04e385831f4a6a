#pragma once
// Input files that several tests write at one fixed path. ctest runs each test in its own process,
// two at a time: a plain write truncates the file another test may be reading (a 0.01 s failure of
// ExtremeBlocks.HeavyAndTinyBlocksRunDownASlope under ctest -j2). Each process writes its own copy
// and renames it into place, which POSIX makes atomic: a reader sees the old file or the new one.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace sylva::testfiles {

inline std::string writeWholeFile(const std::filesystem::path& path, const std::string& text) {
    const std::filesystem::path own = path.string() + "." + std::to_string(::getpid()) + ".tmp";
    std::ofstream(own) << text;
    std::filesystem::rename(own, path);
    return path.string();
}

}  // namespace sylva::testfiles
