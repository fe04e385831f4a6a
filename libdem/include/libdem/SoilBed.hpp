#pragma once
// The soil: fixed spheres laid under a macroscopic surface (a slope profile extruded across the
// slope, or a DTM) that give it its roughness (paper Sect. 2.1.1, 2.2.1, Figs. 6-7).
// The soil is static: it is never integrated, and a query touches only the spheres near a point.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "libdem/ElevationGrid.hpp"
#include "libdem/SlopeProfile.hpp"

namespace sylva::dem {

struct SoilBedParams {
    double radius = 0.7;      // R_soil, m (Sect. 2.1.1: spheres of 1.4 m diameter)
    double roughness = 0.1;   // bump height between neighbours, m; sets the spacing (model-notes.md)
    double width = 200.0;     // extent across the slope (profile terrains), m; y in [0, width]
    std::uint64_t seed = 1;   // row offsets across the slope (Fig. 7)
};

// Centre spacing d of neighbouring soil spheres for a bump height h: h = R - sqrt(R^2 - (d/2)^2)
// (Fig. 6). Throws InputError unless R > 0 and 0 < h <= R.
double soilSpacing(double radius, double roughness);

// Spheres are laid in rows across the slope (constant x). Row r holds perRow spheres at
// y = rowY0[r] + j d, j = 0..perRow-1, and sphere id = r * perRow + j. Rows are sorted by x, so
// the spheres near a point are found by a binary search on x and a division in y.
class SoilBed {
public:
    // Rows at curvilinear spacing d along the profile (from xmin); each centre is R below the
    // profile along the local normal, so the sphere's top touches the profile. Extruded over
    // y in [0, width].
    // Largest bed built: 5e7 spheres (~400 MB of heights) covers ~25 km2 at Table 2's spacing.
    static constexpr double kMaxSpheres = 5e7;

    static SoilBed fromProfile(const SlopeProfile& profile, const SoilBedParams& params);
    // Rows at horizontal spacing d in x over the grid's extent (params.width is not used: the DTM
    // gives the extent), spheres at spacing d in y. Centres stay on that (x, y) lattice and lie
    // R sqrt(1 + |grad z|^2) under the surface, i.e. R from its local tangent plane. The spacing
    // is horizontal, so on a slope of angle theta neighbours along x are d / cos(theta) apart on
    // the surface (bumps a little higher than `roughness`). Throws InputError if a NODATA cell
    // lies under the bed.
    static SoilBed fromGrid(const ElevationGrid& grid, const SoilBedParams& params);

    double radius() const { return radius_; }
    double spacing() const { return spacing_; }
    std::size_t size() const { return centerZ_.size(); }
    std::size_t rows() const { return rowX_.size(); }
    std::uint32_t perRow() const { return perRow_; }
    Eigen::Vector3d center(std::uint32_t id) const;

    // Appends to `out` the ids of the soil spheres whose centres lie within `reach` of p.
    // Cost is proportional to the number of spheres in the box p +- reach, never to size().
    void near(const Eigen::Vector3d& p, double reach, std::vector<std::uint32_t>& out) const;

    double surfaceHeight(double x, double y) const;  // the macroscopic surface (profile or DTM)
    // How fast the surface can rise per metre across, in any horizontal direction:
    // surfaceHeight(q) <= surfaceHeight(p) + steepestRise() |q - p| (horizontal distance). What a
    // height already known says about the heights around it, without asking for them.
    double steepestRise() const { return steepestRise_; }
    bool onProfile() const { return profile_.has_value(); }  // a slope profile extruded sideways, not a DTM
    double dtmCellSize() const { return grid_ ? grid_->cellSize() : 0.0; }  // m; 0 on a profile
    // Distance along the surface from x0 to x1 at cross-slope position y (the run-out measure);
    // negative when x1 < x0.
    double alongSlope(double x0, double x1, double y) const;
    double xmin() const { return xmin_; }
    double xmax() const { return xmax_; }
    double ymin() const { return ymin_; }
    double ymax() const { return ymax_; }
    // "x in [xmin, xmax], y in [ymin, ymax]", for the messages that refuse a point outside it.
    std::string boundsText() const;

    void writeCsv(const std::string& path) const;  // x,y,z,r per sphere (for ParaView / another DEM code)

private:
    struct Row {
        double x, y0;
        std::vector<double> z;  // per sphere of the row (one value repeated on a profile)
    };
    // Sets radius, spacing, the surface's extent and perRow (enough columns to cover [ymin, ymax]).
    SoilBed(const SoilBedParams& params, double xmin, double xmax, double ymin, double ymax);
    // Refuses, before any allocation, a bed of `rows` rows that would exceed kMaxSpheres.
    void requireFits(double rows, const std::string& extent) const;
    void setRows(std::vector<Row> rows);  // sorts by x and flattens

    double radius_ = 0.7, spacing_ = 0.721;
    std::vector<double> rowX_, rowY0_;  // per row, sorted by x: centre x and y of column 0
    std::vector<double> centerZ_;       // per sphere, id = row * perRow_ + j
    std::uint32_t perRow_ = 0;
    double xmin_ = 0, xmax_ = 0, ymin_ = 0, ymax_ = 0;
    double steepestRise_ = 0;
    // the macroscopic surface: exactly one is set
    std::optional<SlopeProfile> profile_;
    std::optional<ElevationGrid> grid_;
};

}  // namespace sylva::dem
