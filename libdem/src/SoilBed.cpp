#include "libdem/SoilBed.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>

#include "libcommon/InputError.hpp"
#include "libcommon/SeededRandom.hpp"

namespace sylva::dem {
namespace {

// The random offset of each row across the slope (Fig. 7), from GSL's mt19937 seeded with
// params.seed (GSL keeps its low 32 bits).
class RowOffsets {
public:
    RowOffsets(std::uint64_t seed, double radius, double spacing)
        : rng_(seed), radius_(radius), spacing_(spacing) {}
    // A row's spheres sit at y = ymin + offset + k d, offset uniform in [0, 2 R_soil] (Fig. 7).
    // Column 0 is the last of them at or below ymin, so that the row also covers [ymin, ymin + offset).
    double nextColumn0(double ymin) {
        const double offset = 2.0 * radius_ * rng_.uniform();
        return ymin + offset - std::ceil(offset / spacing_) * spacing_;
    }

private:
    SeededRandom rng_;
    double radius_, spacing_;
};

}  // namespace

double soilSpacing(double radius, double roughness) {
    if (!(radius > 0) || !std::isfinite(radius))
        throw InputError("terrain.soil_radius_m = " + readableNumber(radius) + ": the soil spheres' radius must be positive");
    if (!(roughness > 0) || !(roughness <= radius))
        throw InputError("terrain.roughness_m = " + readableNumber(roughness) +
                         ": the bump between soil spheres must be in (0, terrain.soil_radius_m = " + readableNumber(radius) +
                         "] m (Fig. 6: a bump of 0 would stack the spheres on one point, one above the radius cannot be made)");
    // h = R - sqrt(R^2 - (d/2)^2) solved for d (Fig. 6)
    return 2.0 * std::sqrt(2.0 * radius * roughness - roughness * roughness);
}

SoilBed::SoilBed(const SoilBedParams& params, double xmin, double xmax, double ymin, double ymax)
    : radius_(params.radius),
      spacing_(soilSpacing(params.radius, params.roughness)),
      xmin_(xmin),
      xmax_(xmax),
      ymin_(ymin),
      ymax_(ymax) {
    if (!(ymax > ymin) || !std::isfinite(ymax - ymin))
        throw InputError("soil bed: the extent across the slope must be positive and finite, got " +
                         std::to_string(ymax - ymin) + " m");
    // Column 0 lies in (ymin - d, ymin], so ceil(width / d) + 2 columns always reach ymax.
    const double columns = std::ceil((ymax - ymin) / spacing_) + 2.0;
    if (columns > 1e8) throw InputError("soil bed: too many spheres across the slope");
    perRow_ = static_cast<std::uint32_t>(columns);
}

void SoilBed::requireFits(double rows, const std::string& extent) const {
    const double spheres = rows * perRow_;
    if (spheres <= kMaxSpheres) return;
    std::ostringstream os;
    os << "soil bed: " << extent << " at " << spacing_ << " m between spheres needs " << spheres
       << " soil spheres, above the " << kMaxSpheres << " (~" << kMaxSpheres * sizeof(double) / 1e6
       << " MB) that fit: a length in mm, or a terrain much larger than a slope?";
    throw InputError(os.str());
}

void SoilBed::setRows(std::vector<Row> rows) {
    if (static_cast<double>(rows.size()) * perRow_ > static_cast<double>(std::numeric_limits<std::uint32_t>::max()))
        throw InputError("soil bed: more spheres than 32-bit ids can number; reduce the terrain");
    // Row centres are not always increasing in x: at a convex break of a profile the centres of
    // the next segment, R below it along its steeper normal, step back upslope.
    std::vector<std::size_t> order(rows.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rows[a].x < rows[b].x; });
    rowX_.reserve(rows.size());
    rowY0_.reserve(rows.size());
    centerZ_.reserve(rows.size() * perRow_);
    for (const std::size_t r : order) {
        rowX_.push_back(rows[r].x);
        rowY0_.push_back(rows[r].y0);
        centerZ_.insert(centerZ_.end(), rows[r].z.begin(), rows[r].z.end());
    }
}

SoilBed SoilBed::fromProfile(const SlopeProfile& profile, const SoilBedParams& params) {
    SoilBed bed(params, profile.xmin(), profile.xmax(), 0.0, params.width);
    bed.profile_ = profile;
    const double R = bed.radius_, d = bed.spacing_;
    RowOffsets offsets(params.seed, R, d);
    const auto& x = profile.xs();
    const auto& z = profile.zs();
    // Linear between vertices, the end segments extended: its steepest segment.
    for (std::size_t k = 0; k + 1 < x.size(); ++k)
        bed.steepestRise_ = std::max(bed.steepestRise_, std::abs(z[k + 1] - z[k]) / (x[k + 1] - x[k]));
    const auto segmentLength = [&](std::size_t i) { return std::hypot(x[i + 1] - x[i], z[i + 1] - z[i]); };
    std::ostringstream extent;
    extent << "a profile " << profile.length() << " m long and " << params.width << " m wide";
    bed.requireFits(std::floor(profile.length() / d) + 1, extent.str());
    std::vector<Row> rows;
    std::size_t i = 0;
    double segmentStart = 0.0, L = segmentLength(0);
    for (long k = 0; k * d <= profile.length(); ++k) {
        const double s = k * d;
        while (s >= segmentStart + L && i + 2 < x.size()) {  // a vertex belongs to the segment after it
            segmentStart += L;
            L = segmentLength(++i);
        }
        const double t = (s - segmentStart) / L, dx = x[i + 1] - x[i], dz = z[i + 1] - z[i];
        // centre = surface point - R n, n = (-dz, dx) / L the upward unit normal of the segment
        const double cx = x[i] + t * dx + R * dz / L, cz = z[i] + t * dz - R * dx / L;
        rows.push_back({cx, offsets.nextColumn0(0.0), std::vector<double>(bed.perRow_, cz)});
    }
    bed.setRows(std::move(rows));
    return bed;
}

SoilBed SoilBed::fromGrid(const ElevationGrid& grid, const SoilBedParams& params) {
    grid.requireDefined(grid.xmin(), grid.xmax(), grid.ymin(), grid.ymax());
    SoilBed bed(params, grid.xmin(), grid.xmax(), grid.ymin(), grid.ymax());
    bed.grid_ = grid;
    // Bilinear in each cell: its slope along x is a mean of those of the cell's two edges along x,
    // along y likewise, so neither exceeds the steeper edge (clamped outside the grid: flat there).
    const std::vector<double>& z = grid.values();
    const auto at = [&](int c, int r) { return z[static_cast<std::size_t>(r) * grid.columns() + c]; };
    for (int r = 0; r + 1 < grid.rows(); ++r)
        for (int c = 0; c + 1 < grid.columns(); ++c) {
            const double zx = std::max(std::abs(at(c + 1, r) - at(c, r)), std::abs(at(c + 1, r + 1) - at(c, r + 1)));
            const double zy = std::max(std::abs(at(c, r + 1) - at(c, r)), std::abs(at(c + 1, r + 1) - at(c + 1, r)));
            bed.steepestRise_ = std::max(bed.steepestRise_, std::hypot(zx, zy) / grid.cellSize());
        }
    const double R = bed.radius_, d = bed.spacing_;
    RowOffsets offsets(params.seed, R, d);
    std::ostringstream extent;
    extent << "a DTM of " << grid.xmax() - grid.xmin() << " m by " << grid.ymax() - grid.ymin() << " m";
    bed.requireFits(std::floor((grid.xmax() - grid.xmin()) / d) + 1, extent.str());
    std::vector<Row> rows;
    for (long k = 0; grid.xmin() + k * d <= grid.xmax(); ++k) {
        Row row{grid.xmin() + k * d, offsets.nextColumn0(grid.ymin()), std::vector<double>(bed.perRow_)};
        for (std::uint32_t j = 0; j < bed.perRow_; ++j) {
            const double y = row.y0 + j * d;
            // The centres stay on the (x, y) lattice so that the index stays implicit, and go down
            // by R / cos(theta) = R sqrt(1 + |grad z|^2): that puts them at distance R from the
            // local tangent plane, so the sphere is tangent to the surface as on a profile (going
            // down by R vertically would leave it sticking out by R (1 - cos theta) on a slope).
            row.z[j] = grid.height(row.x, y) - R * std::sqrt(1.0 + grid.gradient(row.x, y).squaredNorm());
        }
        rows.push_back(std::move(row));
    }
    bed.setRows(std::move(rows));
    return bed;
}

Eigen::Vector3d SoilBed::center(std::uint32_t id) const {
    assert(id < size());
    const std::uint32_t r = id / perRow_, j = id % perRow_;
    return {rowX_[r], rowY0_[r] + j * spacing_, centerZ_[id]};
}

void SoilBed::near(const Eigen::Vector3d& p, double reach, std::vector<std::uint32_t>& out) const {
    if (!(reach >= 0) || !p.allFinite()) return;  // a NaN would otherwise select every row
    const auto first = std::lower_bound(rowX_.begin(), rowX_.end(), p.x() - reach);
    const auto last = std::upper_bound(first, rowX_.end(), p.x() + reach);
    const double lastColumn = perRow_ - 1.0;
    for (auto it = first; it != last; ++it) {
        const std::uint32_t r = static_cast<std::uint32_t>(it - rowX_.begin());
        // One column of margin each side absorbs the rounding of the division; the exact test
        // below decides.
        const double j0 = std::max(0.0, std::ceil((p.y() - reach - rowY0_[r]) / spacing_) - 1.0);
        const double j1 = std::min(lastColumn, std::floor((p.y() + reach - rowY0_[r]) / spacing_) + 1.0);
        if (!(j0 <= j1)) continue;
        for (auto j = static_cast<std::uint32_t>(j0); j <= static_cast<std::uint32_t>(j1); ++j) {
            const std::uint32_t id = r * perRow_ + j;
            if ((center(id) - p).squaredNorm() <= reach * reach) out.push_back(id);
        }
    }
}

double SoilBed::surfaceHeight(double x, double y) const {
    return profile_ ? profile_->height(x) : grid_->height(x, y);
}

std::string SoilBed::boundsText() const {
    return "x in [" + readableNumber(xmin_) + ", " + readableNumber(xmax_) + "], y in [" + readableNumber(ymin_) + ", " +
           readableNumber(ymax_) + "]";
}

double SoilBed::alongSlope(double x0, double x1, double y) const {
    return profile_ ? profile_->abscissa(x1) - profile_->abscissa(x0) : grid_->lengthAlongX(x0, x1, y);
}

void SoilBed::writeCsv(const std::string& path) const {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "w"), &std::fclose);
    if (!f) throw cannotWrite(path);
    bool ok = std::fputs("x,y,z,r\n", f.get()) >= 0;
    for (std::uint32_t id = 0; ok && id < size(); ++id) {
        const Eigen::Vector3d c = center(id);
        ok = std::fprintf(f.get(), "%.6f,%.6f,%.6f,%.6f\n", c.x(), c.y(), c.z(), radius_) > 0;
    }
    if (!ok || std::fflush(f.get()) != 0) throw InputError(path, 0, "write failed (disk full?)");
}

}  // namespace sylva::dem
