#include "libcommon/CsvTable.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "libcommon/InputError.hpp"
#include "libcommon/LineEnds.hpp"

namespace sylva {
namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

std::vector<std::string> splitLine(const std::string& line) {
    std::vector<std::string> out;
    std::string cell;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                cell += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                cell += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            out.push_back(trim(cell));
            cell.clear();
        } else {
            cell += c;
        }
    }
    out.push_back(trim(cell));
    return out;
}

bool blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

}  // namespace

CsvTable CsvTable::read(const std::string& path) {
    if (std::filesystem::is_directory(path)) throw InputError(path, 0, "is a folder, not a CSV file");
    std::ifstream in(path);
    if (!in) throw InputError(path, 0, "cannot open file");
    std::stringstream ss;
    ss << in.rdbuf();
    return parse(ss.str(), path);
}

CsvTable CsvTable::parse(const std::string& text, const std::string& sourceName) {
    CsvTable t;
    t.source_ = sourceName;
    // A UTF-8 byte-order mark from a spreadsheet export goes before anything is read: left on the first
    // line it hid a comment's '#' and made the comment the header.
    const bool marked = text.rfind("\xEF\xBB\xBF", 0) == 0;
    std::istringstream in(withCrOnlyLineEndsAsLineFeeds(marked ? text.substr(3) : text));
    std::string line;
    long lineNo = 0;
    bool haveHeader = false;
    while (std::getline(in, line)) {
        ++lineNo;
        if (blank(line) || line[0] == '#') continue;
        auto cells = splitLine(line);
        if (!haveHeader) {
            for (std::size_t i = 0; i < cells.size(); ++i) {
                if (cells[i].empty()) throw InputError(sourceName, lineNo, "empty column name in header");
                for (std::size_t j = 0; j < i; ++j)
                    if (cells[j] == cells[i])
                        throw InputError(sourceName, lineNo, "column '" + cells[i] + "' appears twice in the header");
            }
            // A European spreadsheet's "CSV" separates fields with ';' (its decimals taking the comma), a
            // tab-separated export with tabs: read with commas, the header was one column and the
            // errors spoke of missing columns that the header visibly held.
            if (cells.size() == 1)
                for (const auto& [separator, name] : {std::pair{';', "';'"}, {'\t', "tabs"}})
                    if (cells[0].find(separator) != std::string::npos)
                        throw InputError(sourceName, lineNo, "the header '" + cells[0] + "' is one column: its fields are separated by " + name +
                                                                 ", sylvarock's by commas (and decimals take a point): save the table as "
                                                                 "comma-separated CSV");
            t.header_ = std::move(cells);
            t.headerLine_ = lineNo;
            haveHeader = true;
            continue;
        }
        if (cells.size() != t.header_.size())
            throw InputError(sourceName, lineNo,
                             "expected " + std::to_string(t.header_.size()) + " fields (as in the header), found " +
                                 std::to_string(cells.size()));
        t.cells_.push_back(std::move(cells));
        t.lines_.push_back(lineNo);
    }
    if (!haveHeader) throw InputError(sourceName, 0, "file is empty (a header row is required)");
    return t;
}

std::optional<std::size_t> CsvTable::index(const std::string& column) const {
    for (std::size_t i = 0; i < header_.size(); ++i)
        if (header_[i] == column) return i;
    return std::nullopt;
}

std::size_t CsvTable::require(const std::string& column) const {
    if (auto i = index(column)) return *i;
    std::string have;
    for (const auto& h : header_) have += (have.empty() ? "" : ",") + h;
    throw InputError(source_, headerLine_, "missing column '" + column + "' (header has: " + have + ")");
}

double CsvTable::number(std::size_t row, std::size_t col) const {
    const std::string& s = cells_[row][col];
    if (s.empty()) fail(row, col, "empty value where a number is required");
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    // strtod also reads C's hexadecimal floats: in a field survey's table "0x10" is a typo, not 16.
    if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v) || s.find_first_of("xX") != std::string::npos)
        fail(row, col, "'" + s + "' is not a finite number");
    return v;
}

long CsvTable::integer(std::size_t row, std::size_t col) const {
    const std::string& s = cells_[row][col];
    if (s.empty()) fail(row, col, "empty value where an integer is required");
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (end != s.c_str() + s.size() || errno == ERANGE) fail(row, col, "'" + s + "' is not an integer");
    return v;
}

void CsvTable::fail(std::size_t row, std::size_t col, const std::string& message) const {
    throw InputError(source_, lines_[row], "column '" + header_[col] + "': " + message);
}

void CsvTable::fail(std::size_t row, const std::string& message) const {
    throw InputError(source_, lines_[row], message);
}

}  // namespace sylva
