#include "libcommon/BuildId.hpp"

#include "sylvarock_build_id.hpp"

namespace sylva {

namespace {
const std::string kMadeBy = "# made by sylvarock ";
const std::string kBuild = "build ";
}  // namespace

const char* buildId() { return SYLVAROCK_BUILD_ID; }

std::string madeByLine() { return kMadeBy + kBuild + buildId(); }

std::string otherBuildNote(const std::string& where, const std::vector<std::string>& storedLines, const std::string& what) {
    std::string madeBy = "an unrecorded build of sylvarock (before 28 Nov. 2026)";
    for (const std::string& line : storedLines) {
        if (line.rfind(kMadeBy, 0) != 0) continue;
        std::string id = line.substr(kMadeBy.size());
        if (id.rfind(kBuild, 0) == 0) id = id.substr(kBuild.size());
        if (id == buildId()) return {};
        madeBy = "sylvarock build " + id;
    }
    return where + ": its runs were made by " + madeBy + ", this is sylvarock build " + buildId() +
           ": if the model changed between them, the runs made now differ from those the first build would have made "
           "(start the " + what + " in a new --out to have every run from this build)";
}

}  // namespace sylva
