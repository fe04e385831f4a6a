#include "libassess/RunRecord.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "libassess/Hashing.hpp"

namespace sylva::assess {

namespace {

constexpr int kChecksumDigits = 16;

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    return cells;
}

bool parseDouble(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtod(text.c_str(), &end);
    return errno == 0 && end == text.c_str() + text.size();
}

bool parseInteger(const std::string& text, long long& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtoll(text.c_str(), &end, 10);
    return errno == 0 && end == text.c_str() + text.size();
}

bool knownReason(const std::string& r) {
    for (auto reason : dem::kStopReasons)
        if (r == dem::toString(reason)) return true;
    return false;
}

}  // namespace

RunRecord toRecord(const dem::RunResult& result) {
    RunRecord r;
    r.run = result.run;
    r.seed = result.seed;
    r.runoutM = result.runoutAlongSlope;
    r.runoutHorizontalM = result.runoutHorizontal;
    r.stopX = result.stop.x();
    r.stopY = result.stop.y();
    r.stopZ = result.stop.z();
    r.energyLineDeg = result.energyLineDeg;
    r.maxSpeed = result.maxSpeed;
    r.treeImpacts = static_cast<long>(result.impacts.size());
    r.reason = dem::toString(result.reason);
    return r;
}

namespace {
std::string lineBody(const RunRecord& r) {
    return std::to_string(r.run) + ',' + std::to_string(r.seed) + ',' + exactText(r.runoutM) + ',' + exactText(r.runoutHorizontalM) +
           ',' + exactText(r.stopX) + ',' + exactText(r.stopY) + ',' + exactText(r.stopZ) + ',' + exactText(r.energyLineDeg) + ',' +
           exactText(r.maxSpeed) + ',' + std::to_string(r.treeImpacts) + ',' + r.reason + ',';
}
}  // namespace

std::string runChecksum(const RunRecord& r) { return toHex(fnv1a64(lineBody(r)), kChecksumDigits); }

std::string formatRunLine(const RunRecord& r) { return lineBody(r) + runChecksum(r); }

std::optional<RunRecord> parseRunLine(const std::string& line) {
    const auto lastComma = line.rfind(',');
    if (lastComma == std::string::npos) return std::nullopt;
    const std::string body = line.substr(0, lastComma + 1);
    if (line.substr(lastComma + 1) != toHex(fnv1a64(body), kChecksumDigits)) return std::nullopt;
    const auto cells = split(line);
    if (cells.size() != 12) return std::nullopt;
    RunRecord r;
    long long run = 0, seed = 0, impacts = 0;
    double* numbers[] = {&r.runoutM, &r.runoutHorizontalM, &r.stopX, &r.stopY, &r.stopZ, &r.energyLineDeg, &r.maxSpeed};
    if (!parseInteger(cells[0], run) || !parseInteger(cells[1], seed) || !parseInteger(cells[9], impacts)) return std::nullopt;
    for (int i = 0; i < 7; ++i)
        if (!parseDouble(cells[2 + i], *numbers[i])) return std::nullopt;
    if (run < 0 || seed < 0 || impacts < 0 || !knownReason(cells[10])) return std::nullopt;
    r.run = static_cast<int>(run);
    r.seed = static_cast<std::uint64_t>(seed);
    r.treeImpacts = static_cast<long>(impacts);
    r.reason = cells[10];
    return r;
}

}  // namespace sylva::assess
