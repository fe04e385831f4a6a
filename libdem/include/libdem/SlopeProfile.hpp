#pragma once
// A slope profile z(x): the macroscopic topography of a 2-D slope, later extruded across the slope
// (paper Sect. 2.2.1). Piecewise linear through the points of a CSV with columns x,z (metres).
#include <vector>
#include <string>

namespace sylva::dem {

class SlopeProfile {
public:
    // Throws InputError if the profile is not usable: sizes differ, fewer than 2 points, a
    // non-finite value, or x not strictly increasing.
    SlopeProfile(std::vector<double> x, std::vector<double> z);
    // Reads columns x and z (other columns are ignored); errors name the file and the line.
    static SlopeProfile readCsv(const std::string& path);

    double xmin() const { return x_.front(); }
    double xmax() const { return x_.back(); }
    double height(double x) const;    // linear interpolation (end segments extended outside)
    double slopeDeg(double x) const;  // angle of the segment under x, positive when z falls with x
    double abscissa(double x) const;  // curvilinear abscissa s(x) along the profile, s(xmin) = 0
    double length() const { return s_.back(); }  // s(xmax)
    // Index i of the segment [x_i, x_{i+1}] that holds x; a vertex belongs to the segment after it,
    // points outside belong to the end segments.
    std::size_t segmentAt(double x) const;
    const std::vector<double>& xs() const { return x_; }
    const std::vector<double>& zs() const { return z_; }

private:
    std::vector<double> x_, z_, s_;  // s_: abscissa of each vertex
    // Every awake stem node asks for the ground under it at every step: equal bins along x, two per
    // segment, each naming a vertex range that holds the answer, so a query searches a few vertices.
    double binsPerMetre_ = 0;
    std::vector<std::size_t> bin_;  // a vertex at or before the bin's start, one segment early against round-off
};

}  // namespace sylva::dem
