#include "libcommon/InputError.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace sylva {

InputError cannotWrite(const std::string& path) {
    const int error = errno;
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) return InputError(path, 0, "is a folder: give a file's name to write");
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec))
        return InputError(path, 0, "cannot write here: the folder " + folder.string() + (fs::exists(folder, ec) ? " is a file" : " does not exist"));
    return InputError(path, 0, std::string("cannot open file for writing: ") + (error ? std::strerror(error) : "unknown reason"));
}

}  // namespace sylva
