#include "libassess/CampaignStore.hpp"

#include <filesystem>
#include <fstream>

#include "libstand/InputError.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

namespace {
const char* const kDesignFile = "design.txt";

bool emptyOrAbsent(const std::string& dir) {
    if (!fs::exists(dir)) return true;
    if (!fs::is_directory(dir)) throw InputError("--out " + dir + ": exists and is not a directory");
    return fs::is_empty(dir);
}

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
    dropUnwrittenDesign(dir_);
    if (emptyOrAbsent(dir_)) {
        if (resume) notes_.push_back(dir_ + " holds no campaign yet: starting a new one");
        fs::create_directories(dir_);
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

std::string CampaignStore::forestSummaryPath(const Campaign& campaign) const {
    return dir_ + "/forests/" + campaign.id + ".csv";
}

}  // namespace sylva::assess
