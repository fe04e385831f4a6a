#pragma once
// The set covariance |W ∩ (W + v)| of a polygon window with holes, exact, in about O(n) per v for
// n edges (the translation edge correction needs it for every pair of points).
//
// By Green's theorem the area of A ∩ B is ½∮(x dy − y dx) over its boundary, which is made of the
// parts of ∂A inside B and the parts of ∂B inside A, each oriented as in its own polygon (outer rings
// counter-clockwise, holes clockwise). Here A = W and B = W + v: the parts of an edge inside the
// other polygon follow from its crossings with the other's edges (a uniform grid of W's edges keeps
// those to the few edges near it) and from whether its ring's first vertex is inside.
//
// Pair vectors along an axis-parallel edge are common with surveyed coordinates, and then the two
// boundaries touch or overlap. Every side-of-line test is decided as if B were shifted by a further
// infinitesimal ε e in a fixed generic direction e (simulation of simplicity, Edelsbrunner & Mücke
// 1990): a test whose value is exactly zero takes the sign of its derivative in ε. The result is the
// limit as ε → 0, which is the set covariance at v itself since it is continuous in v. A point shared
// by two edges is always tested with the same inputs, so the crossings along a ring stay consistent.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "libstand/Window.hpp"

namespace sylva::stand {

class PolygonSetCovariance {
public:
    explicit PolygonSetCovariance(const Window& window);
    double operator()(const Eigen::Vector2d& v) const;

private:
    struct Edge {
        Eigen::Vector2d a, b;  // oriented: the window on the left
    };
    // ½∮(x dy − y dx), about `origin`, over the parts of ∂W whose points x have x − shift in W, each
    // such point moving by ε `moving` (the perturbation, in W's frame).
    double boundaryInside(const Eigen::Vector2d& shift, const Eigen::Vector2d& origin, const Eigen::Vector2d& moving) const;
    bool edgeInside(const Edge& edge, const Eigen::Vector2d& shift, const Eigen::Vector2d& origin, const Eigen::Vector2d& moving,
                    bool in, double& sum) const;
    bool nearEdges(const Eigen::AlignedBox2d& box) const;  // whether the box meets a cell holding an edge
    // Whether p (in W's frame) is in W; `clear` false if p is within `tolerance_` of the boundary,
    // where the answer would depend on rounding.
    bool inside(const Eigen::Vector2d& p, bool& clear) const;
    template <class F>
    void forCellsAlong(const Eigen::Vector2d& p, const Eigen::Vector2d& q, F&& f) const;
    template <class F>
    void forEdgesNear(const Eigen::Vector2d& p, const Eigen::Vector2d& q, F&& f) const;

    Window window_;
    std::vector<Edge> edges_;              // in W's frame: its lower corner at the origin
    std::vector<std::size_t> ringStarts_;  // index of each ring's first edge, and the end
    Eigen::Vector2d corner_;               // W's lower corner
    double area_ = 0, tolerance_ = 0;
    // Uniform grid of the edges, about one edge per cell.
    double cell_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<int>> cells_;
    std::vector<long> occupied_;  // prefix sums of the cells' edge counts, (nx + 1) x (ny + 1)
    // Consecutive edges of a ring, kChain at a time: ½Σ cross(a − o, b − o) = ½(sumCross − o × sumVector).
    static constexpr std::size_t kChain = 16;
    struct Chain {
        std::size_t edges = 0;
        Eigen::AlignedBox2d box;
        double sumCross = 0;
        Eigen::Vector2d sumVector = Eigen::Vector2d::Zero();
    };
    std::vector<Chain> chains_;
    std::vector<std::size_t> chainStarts_;  // each ring's first chain
};

}  // namespace sylva::stand
