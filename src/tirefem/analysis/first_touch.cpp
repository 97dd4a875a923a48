#include "tirefem/analysis/first_touch.hpp"

#include <cmath>
#include <stdexcept>

namespace tirefem {

namespace {

// The deepest point at δz: its index and penetration.
std::pair<std::size_t, double> deepest(const std::vector<Eigen::Vector3d>& positions, const SupportSurface& support,
                                       double deflection) {
  std::size_t best = 0;
  double g_max = -1e300;
  for (std::size_t q = 0; q < positions.size(); ++q) {
    const double g = support.penetration(positions[q], deflection).value;
    if (g > g_max) g_max = g, best = q;
  }
  return {best, g_max};
}

}  // namespace

double first_touch_deflection(const std::vector<Eigen::Vector3d>& positions, const SupportSurface& support) {
  if (positions.empty()) throw std::invalid_argument("first_touch_deflection: no tread points");
  double deflection = 0.0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const auto [q, g] = deepest(positions, support, deflection);
    // ∂g/∂δz of the deepest point; max over points is piecewise smooth, so Newton on it converges once
    // the deepest point no longer changes.
    const double slope = -support.penetration(positions[q], deflection).gradient.z();
    if (!(slope > 0)) throw std::runtime_error("first_touch_deflection: the support does not approach the tyre");
    const double step = g / slope;
    deflection -= step;
    if (std::abs(step) <= 1e-13 * (1.0 + std::abs(deflection))) break;
  }
  return deflection;
}

double estimated_deflection_for_load(const std::vector<TreadPoint>& points,
                                     const std::vector<Eigen::Vector3d>& positions, const SupportSurface& support,
                                     double pressure, bool half_model, double load, double from, double to) {
  const auto membrane_load = [&](double deflection) {
    double area = 0.0;
    for (std::size_t q = 0; q < points.size(); ++q)
      if (support.penetration(positions[q], deflection).value > 0) area += points[q].weight;
    return pressure * area * (half_model ? 2.0 : 1.0);
  };
  if (!(to > from) || membrane_load(to) < load) return to;
  double lo = from, hi = to;
  for (int k = 0; k < 40 && hi - lo > 1e-3; ++k) {
    const double mid = 0.5 * (lo + hi);
    (membrane_load(mid) < load ? lo : hi) = mid;
  }
  return hi;  // the load is reached there
}

}  // namespace tirefem
