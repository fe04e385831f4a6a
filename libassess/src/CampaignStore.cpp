#include "libassess/CampaignStore.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "libstand/InputError.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

namespace {
const char* const kDesignFile = "design.txt";

// A folder holding only the design's temporary file is a campaign killed before its design was
// written (nothing else is written before it): the file goes, and the campaign starts afresh.
void dropUnwrittenDesign(const std::string& dir) {
    const fs::path unwritten = fs::path(dir) / (std::string(kDesignFile) + ".tmp");
    if (!fs::is_directory(dir) || !fs::exists(unwritten)) return;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path() != unwritten) return;
    fs::remove(unwritten);
}

void writeDesign(const std::string& path, const AssessmentDesign& design) {
    std::ofstream out(path + ".tmp", std::ios::trunc);
    out << designText(design);
    if (!out.flush()) throw InputError(path, 0, "cannot write the design");
    out.close();
    fs::rename(path + ".tmp", path);
}
}  // namespace

CampaignStore::CampaignStore(std::string dir, const AssessmentDesign& design, const std::vector<Campaign>& plan, bool resume)
    : dir_(std::move(dir)) {
    const std::string designPath = dir_ + "/" + kDesignFile;
    if (fs::exists(dir_) && !fs::is_directory(dir_)) throw InputError("--out " + dir_ + ": exists and is not a directory");
    fs::create_directories(dir_);
    lockFolder();
    dropUnwrittenDesign(dir_);
    if (fs::is_empty(dir_)) {
        if (resume) notes_.push_back(dir_ + " holds no campaign yet: starting a new one");
        writeDesign(designPath, design);
    } else if (!resume) {
        throw InputError("--out " + dir_ + " is not empty: use --resume to continue the campaign in it, or another --out");
    } else if (!fs::exists(designPath)) {
        throw InputError(designPath, 0, "missing: " + dir_ + " is not the output of sylvarock assess, nothing to resume");
    } else {
        requireSameDesign(designPath, design);
        resumed_ = true;
    }
    fs::create_directories(dir_ + "/runs");
    fs::create_directories(dir_ + "/forests");
    for (const auto& c : plan)
        logs_.push_back(std::make_unique<RunLog>(dir_ + "/runs/" + c.id + ".csv", c.runs, c.runSeed, notes_));
}

void CampaignStore::lockFolder() {
    lock_ = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (lock_ < 0) throw InputError("--out " + dir_ + ": cannot open the folder: " + std::strerror(errno));
    if (::flock(lock_, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        ::close(lock_);
        lock_ = -1;
        if (error == EWOULDBLOCK)
            throw InputError("--out " + dir_ + " is being written by another sylvarock assess (it holds the folder's lock): "
                             "wait for it to end, or stop it, before resuming; two writers would mix their runs");
        throw InputError("--out " + dir_ + ": cannot lock the folder: " + std::strerror(error));
    }
}

CampaignStore::~CampaignStore() {
    if (lock_ >= 0) ::close(lock_);  // releases the lock
}

std::string CampaignStore::forestSummaryPath(const Campaign& campaign) const {
    return dir_ + "/forests/" + campaign.id + ".csv";
}

}  // namespace sylva::assess
