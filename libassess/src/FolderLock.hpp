#pragma once
// One writer per output folder: an exclusive flock on the folder itself, held while the object
// lives and released however the process ends. A second `assess` or `hazard` on the same --out (a
// resume started while the first still runs, two cluster jobs given one folder) is refused instead
// of mixing its runs, or its outputs, into the first one's.
#include <string>

namespace sylva::assess {

class FolderLock {
public:
    // InputError naming the folder and `command` ("assess", "hazard") if another process holds it.
    FolderLock(const std::string& dir, const std::string& command);
    ~FolderLock();
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    int descriptor_ = -1;
};

}  // namespace sylva::assess
