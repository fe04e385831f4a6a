#include "FolderLock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "libcommon/InputError.hpp"

namespace sylva::assess {

FolderLock::FolderLock(const std::string& dir, const std::string& command) {
    descriptor_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (descriptor_ < 0) throw InputError("--out " + dir + ": cannot open the folder: " + std::strerror(errno));
    if (::flock(descriptor_, LOCK_EX | LOCK_NB) == 0) return;
    const int error = errno;
    ::close(descriptor_);
    if (error == EWOULDBLOCK)
        throw InputError("--out " + dir + " is being written by another sylvarock " + command +
                         " (it holds the folder's lock): wait for it to end, or stop it, before writing there again (a "
                         "new run or a resume); two writers would mix their runs");
    throw InputError("--out " + dir + ": cannot lock the folder: " + std::strerror(error));
}

FolderLock::~FolderLock() { ::close(descriptor_); }

}  // namespace sylva::assess
