#include "libdem/ElevationGrid.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "libcommon/InputError.hpp"
#include "libdem/EarthRelief.hpp"

namespace sylva::dem {
namespace {

std::vector<std::string> tokens(const std::string& line) {
    std::istringstream in(line);  // '\r' of Windows files counts as white space here
    std::vector<std::string> out;
    for (std::string t; in >> t;) out.push_back(t);
    return out;
}

std::optional<double> parseNumber(const std::string& s) {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
    return v;
}

const char* const kUndeclaredNoData =
    "a NODATA value the file does not declare? Declare it (NODATA_value in an ESRI ASCII header; gdal_translate "
    "-a_nodata for other formats)";

std::string offEarth(double z) {
    return "height " + readableNumber(z) + " m is beyond " + kEarthsRelief + ": " + kUndeclaredNoData;
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

struct HeaderValue {
    double value;
    long line;
};

// The ESRI ASCII header: "key value" lines before the first line of numbers, keys in any order
// and any case.
class AscHeader {
public:
    explicit AscHeader(std::string path) : path_(std::move(path)) {}

    void add(const std::vector<std::string>& t, long line) {
        const std::string key = lower(t[0]);
        static const char* const known[] = {"ncols",     "nrows",     "xllcorner", "xllcenter",
                                            "yllcorner", "yllcenter", "cellsize",  "nodata_value"};
        if (std::find(std::begin(known), std::end(known), key) == std::end(known))
            throw InputError(path_, line,
                             "unknown header key '" + t[0] +
                                 "' (expected ncols, nrows, xllcorner|xllcenter, yllcorner|yllcenter, cellsize, "
                                 "NODATA_value)");
        if (t.size() != 2) throw InputError(path_, line, "header line must be '" + t[0] + " VALUE'");
        if (values_.count(key)) throw InputError(path_, line, "header key '" + t[0] + "' appears twice");
        const auto v = parseNumber(t[1]);
        if (!v) throw InputError(path_, line, t[0] + ": '" + t[1] + "' is not a finite number");
        values_[key] = {*v, line};
    }

    // `end` is the line where the header ended (the first line of values), named when a key is missing.
    double require(const std::string& key, long end) const {
        const auto it = values_.find(key);
        if (it == values_.end()) throw InputError(path_, end, "the header ends without '" + key + "'");
        return it->second.value;
    }
    std::optional<HeaderValue> find(const std::string& key) const {
        const auto it = values_.find(key);
        return it == values_.end() ? std::nullopt : std::optional<HeaderValue>(it->second);
    }
    int count(const std::string& key, long end) const {
        const double v = require(key, end);
        const long line = values_.at(key).line;
        if (v != std::floor(v) || v < 2 || v > 1e7)
            throw InputError(path_, line, key + " must be an integer >= 2 (bilinear heights need 2 x 2 cells)");
        return static_cast<int>(v);
    }
    // Centre of the first cell along one axis: from "<axis>llcenter" or "<axis>llcorner" + cell / 2.
    double firstCentre(const std::string& axis, double cell, long end) const {
        const auto corner = find(axis + "llcorner"), centre = find(axis + "llcenter");
        if (corner && centre)
            throw InputError(path_, std::max(corner->line, centre->line),
                             "give either " + axis + "llcorner or " + axis + "llcenter, not both");
        if (centre) return centre->value;
        return require(axis + "llcorner", end) + 0.5 * cell;
    }

private:
    std::string path_;
    std::map<std::string, HeaderValue> values_;
};

}  // namespace

ElevationGrid ElevationGrid::readAsc(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, "cannot open file");
    // A GeoTIFF (or any binary raster) read as text failed on its first bytes as a header key.
    std::string start(4, ' ');
    in.read(&start[0], 4);
    start.resize(static_cast<std::size_t>(in.gcount()));
    if (start.find('\0') != std::string::npos)  // TIFF's "II*\0" and "MM\0*", and most other binary formats
        throw InputError(path, 0, "a binary file (a GeoTIFF?): terrain.dtm reads ESRI ASCII grids; convert it with "
                                  "gdal_translate -of AAIGrid, or map on it with sylvarock hazard --dtm, which reads any raster GDAL does");
    in.clear();
    in.seekg(0);
    ElevationGrid g;
    g.source_ = path;
    AscHeader header(path);
    std::optional<double> nodata;
    std::vector<std::vector<double>> fileRows;  // north first, as in the file
    std::string line;
    long lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        // A UTF-8 byte-order mark (some editors write one) would hide the first header key.
        if (lineNo == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
        const auto t = tokens(line);
        if (t.empty()) continue;
        const bool inHeader = g.ncols_ == 0;
        if (inHeader && std::isalpha(static_cast<unsigned char>(t[0][0]))) {
            header.add(t, lineNo);
            continue;
        }
        if (inHeader) {  // first line of values: the header is complete
            g.cell_ = header.require("cellsize", lineNo);
            // Metres of a projected CRS: sub-centimetre cells are degrees (project the DTM first),
            // kilometre cells no rockfall DTM has.
            if (!(g.cell_ >= 0.01 && g.cell_ <= 1000))
                throw InputError(path, header.find("cellsize")->line,
                                 "cellsize " + readableNumber(g.cell_) + " is outside [0.01, 1000] m (a DTM in "
                                 "geographic degrees? reproject it to metres)");
            g.ncols_ = header.count("ncols", lineNo);
            g.nrows_ = header.count("nrows", lineNo);
            g.x0_ = header.firstCentre("x", g.cell_, lineNo);
            g.y0_ = header.firstCentre("y", g.cell_, lineNo);
            // Beyond 1e8 m a cell no longer adds to a coordinate in double precision.
            for (const std::string axis : {"x", "y"}) {
                const double first = axis == "x" ? g.x0_ : g.y0_;
                if (std::abs(first) <= 1e8) continue;
                const auto given = header.find(axis + "llcorner") ? header.find(axis + "llcorner") : header.find(axis + "llcenter");
                throw InputError(path, given->line, axis + "ll corner or centre " + readableNumber(first) +
                                                        " is beyond 1e8 m: not a projected map coordinate");
            }
            if (const auto nd = header.find("nodata_value")) nodata = nd->value;
        }
        if (static_cast<int>(fileRows.size()) == g.nrows_)
            throw InputError(path, lineNo, "more rows of values than nrows = " + std::to_string(g.nrows_));
        if (static_cast<int>(t.size()) != g.ncols_)
            throw InputError(path, lineNo,
                             "row " + std::to_string(fileRows.size() + 1) + " has " + std::to_string(t.size()) +
                                 " values, ncols = " + std::to_string(g.ncols_) + " (one row of the grid per line)");
        std::vector<double> row;
        row.reserve(t.size());
        for (std::size_t c = 0; c < t.size(); ++c) {
            const auto v = parseNumber(t[c]);
            if (!v)
                throw InputError(path, lineNo,
                                 "value " + std::to_string(c + 1) + ": '" + t[c] + "' is not a finite number");
            const bool noData = nodata && *v == *nodata;
            if (!noData && !onEarth(*v)) throw InputError(path, lineNo, "value " + std::to_string(c + 1) + ": " + offEarth(*v));
            row.push_back(noData ? std::numeric_limits<double>::quiet_NaN() : *v);
        }
        fileRows.push_back(std::move(row));
        g.rowLine_.push_back(lineNo);
    }
    if (g.ncols_ == 0) throw InputError(path, lineNo, "no grid values after the header");
    if (static_cast<int>(fileRows.size()) != g.nrows_)
        throw InputError(path, lineNo,
                         "found " + std::to_string(fileRows.size()) + " rows of values, nrows = " +
                             std::to_string(g.nrows_));
    // The file runs north to south; row 0 of the grid is the southern one.
    std::reverse(fileRows.begin(), fileRows.end());
    std::reverse(g.rowLine_.begin(), g.rowLine_.end());
    g.z_.reserve(static_cast<std::size_t>(g.ncols_) * g.nrows_);
    for (const auto& row : fileRows) g.z_.insert(g.z_.end(), row.begin(), row.end());
    g.complete_ = g.noDataCells() == 0;
    g.refuseUndeclaredNoData();
    return g;
}

ElevationGrid::CellRange ElevationGrid::cellsUnder(double x0, double x1, double y0, double y1) const {
    const auto lo = [&](double v, double origin, int n) {
        return static_cast<int>(std::floor(std::clamp((v - origin) / cell_, 0.0, n - 1.0)));
    };
    const auto hi = [&](double v, double origin, int n) {
        return static_cast<int>(std::ceil(std::clamp((v - origin) / cell_, 0.0, n - 1.0)));
    };
    return {lo(std::min(x0, x1), x0_, ncols_), hi(std::max(x0, x1), x0_, ncols_), lo(std::min(y0, y1), y0_, nrows_),
            hi(std::max(y0, y1), y0_, nrows_)};
}

void ElevationGrid::requireDefined(double x0, double x1, double y0, double y1) const {
    if (!std::isfinite(x0) || !std::isfinite(x1) || !std::isfinite(y0) || !std::isfinite(y1))
        throw std::invalid_argument("ElevationGrid::requireDefined: the rectangle is not finite");
    if (complete_) return;
    const CellRange r = cellsUnder(x0, x1, y0, y1);
    // north first, so that the first error reported is the first in the file
    for (int row = r.r1; row >= r.r0; --row)
        for (int col = r.c0; col <= r.c1; ++col)
            if (std::isnan(at(col, row))) failNoData(col, row);
}

ElevationGrid ElevationGrid::fromValues(int columns, int rows, double x0, double y0, double cellSize, std::vector<double> z,
                                        std::string source) {
    if (columns < 2 || rows < 2) throw std::invalid_argument("ElevationGrid: a grid needs at least 2 x 2 cells");
    if (z.size() != static_cast<std::size_t>(columns) * rows) throw std::invalid_argument("ElevationGrid: values do not fill the grid");
    if (!(cellSize > 0) || !std::isfinite(x0) || !std::isfinite(y0)) throw std::invalid_argument("ElevationGrid: bad geometry");
    ElevationGrid g;
    g.ncols_ = columns;
    g.nrows_ = rows;
    g.x0_ = x0;
    g.y0_ = y0;
    g.cell_ = cellSize;
    g.z_ = std::move(z);
    g.source_ = std::move(source);
    const auto off = std::find_if(g.z_.begin(), g.z_.end(), [](double v) { return !std::isnan(v) && !onEarth(v); });
    if (off != g.z_.end()) {
        const long i = off - g.z_.begin();
        throw InputError(g.source_, 0, g.cellPlace(static_cast<int>(i % columns), static_cast<int>(i / columns)) + ": " + offEarth(*off));
    }
    g.complete_ = g.noDataCells() == 0;
    return g;
}

void ElevationGrid::refuseUndeclaredNoData() const {
    for (int row = nrows_ - 1; row >= 0; --row)  // north first: the first error reported is the first in the file
        for (int col = 0; col < ncols_; ++col) {
            const double z = at(col, row);
            if (std::isnan(z)) continue;
            for (const auto& [c, r] : {std::pair<int, int>{col + 1, row}, std::pair<int, int>{col, row - 1}}) {
                if (c >= ncols_ || r < 0 || std::isnan(at(c, r)) || !impossibleStep(at(c, r) - z, cell_)) continue;
                // The lower of the two: markers within Earth's relief are large negatives (positive
                // ones, 9999 or 32767, lie beyond it), and in a DTM clipped to a catchment they may
                // outnumber the ground.
                const bool first = z < at(c, r);
                const int lowCol = first ? col : c, lowRow = first ? row : r;
                const double low = std::min(z, at(c, r)), high = std::max(z, at(c, r));
                throw InputError(source_, rowLine_.empty() ? 0 : rowLine_[lowRow],
                                 cellPlace(lowCol, lowRow) + ": height " + readableNumber(low) + " m lies " +
                                     readableNumber(std::round(high - low)) + " m below its neighbour's (" +
                                     readableNumber(std::round(high * 100) / 100) + " m) over a cell of " + readableNumber(cell_) +
                                     " m, " + kImpossibleStep + ": " + kUndeclaredNoData);
            }
        }
}

std::string ElevationGrid::cellPlace(int col, int row) const {
    if (!rowLine_.empty()) return "value " + std::to_string(col + 1);
    return "cell (column " + std::to_string(col + 1) + ", row " + std::to_string(nrows_ - row) + ", counted from 1 at the north-west corner)";
}

long ElevationGrid::noDataCells() const {
    return static_cast<long>(std::count_if(z_.begin(), z_.end(), [](double v) { return std::isnan(v); }));
}

void ElevationGrid::failNoData(int col, int row) const {
    throw InputError(source_, rowLine_.empty() ? 0 : rowLine_[row],
                     cellPlace(col, row) + " is NODATA, but the terrain needs it (cell centre x = " + std::to_string(x0_ + col * cell_) +
                         ", y = " + std::to_string(y0_ + row * cell_) + ")");
}

double ElevationGrid::height(double x, double y) const {
    if (!std::isfinite(x) || !std::isfinite(y)) return std::numeric_limits<double>::quiet_NaN();
    requireDefined(x, x, y, y);
    const double fx = std::clamp((x - x0_) / cell_, 0.0, ncols_ - 1.0);
    const double fy = std::clamp((y - y0_) / cell_, 0.0, nrows_ - 1.0);
    const int c = std::min(static_cast<int>(fx), ncols_ - 2), r = std::min(static_cast<int>(fy), nrows_ - 2);
    const double tx = fx - c, ty = fy - r;
    // A corner of weight 0 may be NODATA (NaN): leave it out instead of multiplying NaN by 0.
    const auto term = [&](double w, int col, int row) { return w == 0.0 ? 0.0 : w * at(col, row); };
    return term((1 - tx) * (1 - ty), c, r) + term(tx * (1 - ty), c + 1, r) + term((1 - tx) * ty, c, r + 1) +
           term(tx * ty, c + 1, r + 1);
}

Eigen::Vector2d ElevationGrid::gradient(double x, double y) const {
    if (!std::isfinite(x) || !std::isfinite(y)) return Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
    const double ux = (x - x0_) / cell_, uy = (y - y0_) / cell_;
    const double fx = std::clamp(ux, 0.0, ncols_ - 1.0), fy = std::clamp(uy, 0.0, nrows_ - 1.0);
    const int c = std::min(static_cast<int>(fx), ncols_ - 2), r = std::min(static_cast<int>(fy), nrows_ - 2);
    requireDefined(x0_ + c * cell_, x0_ + (c + 1) * cell_, y0_ + r * cell_, y0_ + (r + 1) * cell_);
    const double tx = fx - c, ty = fy - r;
    const double zx = ((1 - ty) * (at(c + 1, r) - at(c, r)) + ty * (at(c + 1, r + 1) - at(c, r + 1))) / cell_;
    const double zy = ((1 - tx) * (at(c, r + 1) - at(c, r)) + tx * (at(c + 1, r + 1) - at(c + 1, r))) / cell_;
    // Outside the grid the height is clamped, so it does not vary across that edge.
    const bool insideX = ux >= 0.0 && ux <= ncols_ - 1.0, insideY = uy >= 0.0 && uy <= nrows_ - 1.0;
    return {insideX ? zx : 0.0, insideY ? zy : 0.0};
}

double ElevationGrid::lengthAlongX(double x0, double x1, double y) const {
    if (!std::isfinite(x0) || !std::isfinite(x1) || !std::isfinite(y)) return std::numeric_limits<double>::quiet_NaN();
    if (x1 < x0) return -lengthAlongX(x1, x0, y);
    double length = 0.0, xa = x0, za = height(x0, y);
    // kinks of the line y = const: the cell-centre columns strictly between x0 and x1
    const int first = static_cast<int>(std::floor(std::clamp((x0 - x0_) / cell_, -1.0, double(ncols_)))) + 1;
    for (int c = first; c < ncols_; ++c) {
        const double xb = x0_ + c * cell_;
        if (xb >= x1) break;
        if (xb <= xa) continue;
        const double zb = height(xb, y);
        length += std::hypot(xb - xa, zb - za);
        xa = xb;
        za = zb;
    }
    return length + std::hypot(x1 - xa, height(x1, y) - za);
}

}  // namespace sylva::dem
