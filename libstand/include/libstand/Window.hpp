#pragma once
// The observation window of a point pattern: an inventory plot or the extent of a virtual forest.
// Either an axis-aligned rectangle or a simple polygon, possibly with holes (rocks, roads, gaps a
// plot leaves out), x, y in metres.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace sylva::stand {

// z of the cross product of two plane vectors.
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }
// Area of a polygon ring, positive when counter-clockwise (shoelace formula).
double signedArea(const std::vector<Eigen::Vector2d>& ring);

class Window {
public:
    // Throws InputError if xmax <= xmin or ymax <= ymin (a degenerate window).
    static Window rectangle(double xmin, double ymin, double xmax, double ymax);
    // A simple polygon with optional holes (each ring's orientation is normalised to
    // counter-clockwise; a closing vertex equal to the first is dropped). Throws InputError if a ring
    // has fewer than 3 distinct vertices, zero area or intersects itself, or if a hole is not
    // strictly inside the outer ring or meets another hole.
    static Window polygon(std::vector<Eigen::Vector2d> outer, std::vector<std::vector<Eigen::Vector2d>> holes = {});
    // "POLYGON((x y, x y, ...))", with holes "POLYGON((outer ring), (hole), (hole) ...)".
    static Window fromWkt(const std::string& wkt);

    bool isRectangle() const { return rectangle_; }
    double area() const { return area_; }            // the holes' areas taken out
    double perimeter() const { return perimeter_; }  // the holes' boundaries included
    Eigen::Vector2d lower() const { return lo_; }  // bounding box
    Eigen::Vector2d upper() const { return hi_; }
    const std::vector<Eigen::Vector2d>& vertices() const { return rings_.front(); }  // the outer ring's
    // The outer ring, then the holes, each counter-clockwise (a rectangle: its four corners).
    const std::vector<std::vector<Eigen::Vector2d>>& rings() const { return rings_; }

    // Closed window: points on the boundary (a hole's included) are inside.
    bool contains(const Eigen::Vector2d& p) const;
    // Distance from p (inside) to the nearest point of the boundary.
    double distanceToBoundary(const Eigen::Vector2d& p) const;
    std::string describe() const;  // "rectangle [0,50]x[0,50]", "polygon of 7 vertices [with 2 holes]"
    // Throws InputError unless the window could be a field plot or a stand: area in [1 m2, 1e10 m2]
    // (a 1e-9 m wide plot gave N = 3e22 stems/ha; coordinates in km give such windows).
    void requirePlotSize() const;

private:
    Window() = default;
    bool rectangle_ = false;
    double area_ = 0, perimeter_ = 0;
    Eigen::Vector2d lo_{0, 0}, hi_{0, 0};
    std::vector<std::vector<Eigen::Vector2d>> rings_;
};

}  // namespace sylva::stand
