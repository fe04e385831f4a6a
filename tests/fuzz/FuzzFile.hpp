#pragma once
// The fuzz targets' shared plumbing: our readers take file paths, so each input is written to a file
// of this process's own scratch folder first. A reader may refuse an input only with InputError (a
// message naming the file, line or key); anything else escaping it — another exception, a crash, a
// sanitizer report, a hang, memory beyond libFuzzer's -rss_limit_mb — is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace sylva::fuzz {

inline const std::filesystem::path& scratch() {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("sylvarock-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

inline std::string text(const std::uint8_t* data, std::size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

// Writes `contents` to the scratch folder's `name` and returns its path.
inline std::string file(const std::string& name, const std::string& contents) {
    const std::string path = (scratch() / name).string();
    std::ofstream(path, std::ios::binary | std::ios::trunc) << contents;
    return path;
}

}  // namespace sylva::fuzz
