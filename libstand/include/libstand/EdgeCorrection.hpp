#pragma once
// Edge-correction weights for second-order statistics (K, g) of a pattern seen through a window W:
// a pair of points near the boundary has partners outside W that were not observed, so it is
// up-weighted. Both weights follow spatstat (edge.Trans, edge.Ripley), including its cap of 100.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "libstand/Window.hpp"

namespace sylva::stand {

class PolygonSetCovariance;

// Translation correction (Ohser & Stoyan): w(v) = |W| / |W ∩ (W + v)| for the pair vector v.
class TranslationCorrection {
public:
    explicit TranslationCorrection(const Window& window);
    // Set covariance |W ∩ (W + v)|, m². Exact for rectangles and polygons (no pixel approximation).
    double setCovariance(const Eigen::Vector2d& v) const;
    double weight(const Eigen::Vector2d& v) const;  // capped at maxWeight (spatstat's maxedgewt)

private:
    Window window_;
    std::shared_ptr<const PolygonSetCovariance> polygon_;  // null for a rectangle (closed form)
};

// Fraction of the circle of radius r about c (c inside W) whose circumference lies inside W.
double circleFractionInside(const Window& window, const Eigen::Vector2d& c, double r);

// Ripley's isotropic correction: 1 / circleFractionInside, clamped to [1, maxWeight] as spatstat does.
double isotropicWeight(const Window& window, const Eigen::Vector2d& c, double r);

inline constexpr double maxEdgeWeight = 100;  // spatstat.options("maxedgewt") and edge.Ripley(maxweight)

}  // namespace sylva::stand
