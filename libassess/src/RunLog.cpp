#include "libassess/RunLog.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "libdem/Campaign.hpp"
#include "libstand/InputError.hpp"

namespace sylva::assess {

RunLog::RunLog(std::string path, int runs, std::uint64_t campaignSeed, std::vector<std::string>& notes)
    : path_(std::move(path)), runs_(runs) {
    bool clean = true;
    if (std::filesystem::exists(path_)) {
        std::ifstream in(path_, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::size_t start = 0;
        long lineNo = 0;
        while (start < text.size()) {
            ++lineNo;
            const auto end = text.find('\n', start);
            const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
            start = end == std::string::npos ? text.size() : end + 1;
            if (lineNo == 1) {
                if (line != runLogHeader())
                    throw InputError(path_, 1, "not a run log of sylvarock assess (expected the header '" + runLogHeader() + "')");
                if (end == std::string::npos) clean = false;
                continue;
            }
            if (end == std::string::npos) {
                notes.push_back(path_ + ":" + std::to_string(lineNo) + ": dropped a line cut short (interrupted run); it is run again");
                clean = false;
                break;
            }
            const auto record = parseRunLine(line);
            if (!record) {
                notes.push_back(path_ + ":" + std::to_string(lineNo) + ": dropped a damaged line (checksum mismatch); it is run again");
                clean = false;
                continue;
            }
            if (record->run >= runs_)
                throw InputError(path_, lineNo, "run " + std::to_string(record->run) + " is outside this campaign's " +
                                                    std::to_string(runs_) + " runs");
            if (record->seed != dem::runSeed(campaignSeed, record->run))
                throw InputError(path_, lineNo, "run " + std::to_string(record->run) + " has seed " + std::to_string(record->seed) +
                                                    ", not this campaign's " + std::to_string(dem::runSeed(campaignSeed, record->run)));
            const auto [it, inserted] = records_.emplace(record->run, *record);
            if (!inserted && formatRunLine(it->second) != line)
                throw InputError(path_, lineNo, "run " + std::to_string(record->run) + " appears twice with different results");
            if (!inserted) clean = false;
        }
        if (lineNo == 0) clean = false;
    } else {
        clean = false;
    }
    if (!clean) rewrite();
    file_ = std::fopen(path_.c_str(), "ab");
    if (!file_) throw InputError(path_, 0, std::string("cannot open for appending: ") + std::strerror(errno));
}

RunLog::~RunLog() {
    if (file_) std::fclose(file_);
}

std::vector<int> RunLog::missingRuns() const {
    std::vector<int> missing;
    for (int i = 0; i < runs_; ++i)
        if (!records_.count(i)) missing.push_back(i);
    return missing;
}

void RunLog::append(const RunRecord& record) {
    const std::string line = formatRunLine(record) + '\n';
    if (std::fwrite(line.data(), 1, line.size(), file_) != line.size() || std::fflush(file_) != 0)
        throw InputError(path_, 0, std::string("cannot write: ") + std::strerror(errno));
    records_[record.run] = record;
}

// Written beside and renamed over the log, so that a kill during the rewrite leaves either log whole.
void RunLog::rewrite() const {
    const std::string tmp = path_ + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw InputError(tmp, 0, std::string("cannot write: ") + std::strerror(errno));
        out << runLogHeader() << '\n';
        for (const auto& [run, record] : records_) out << formatRunLine(record) << '\n';
        if (!out.flush()) throw InputError(tmp, 0, "cannot write");
    }
    std::filesystem::rename(tmp, path_);
}

}  // namespace sylva::assess
