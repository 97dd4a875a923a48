#include "tirefem/magic_formula/fit_points.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "tirefem/magic_formula/evaluator.hpp"

namespace tirefem::magic_formula_fit {

double measured(FitGroup group, const TyreTestPoint& p) {
  return group == FitGroup::pure_longitudinal ? p.Fx : (group == FitGroup::pure_lateral ? p.Fy : p.Mz);
}

double slip(FitGroup group, const TyreTestPoint& p) { return group == FitGroup::pure_longitudinal ? p.kappa : p.alpha; }

double model(FitGroup group, const MagicFormulaCoefficients& c, const TyreTestPoint& p) {
  switch (group) {
    case FitGroup::pure_longitudinal: return pure_longitudinal_force(c, p.Fz, p.kappa, p.gamma).Fx0;
    case FitGroup::pure_lateral: return pure_lateral_force(c, p.Fz, p.alpha, p.gamma).Fy0;
    case FitGroup::aligning: {
      const PureLateralForce lateral = pure_lateral_force(c, p.Fz, p.alpha, p.gamma);
      return pure_aligning_moment(c, p.Fz, p.alpha, p.gamma, lateral).Mz0;
    }
  }
  return 0;
}

std::vector<double> distinct_values(std::vector<double> values, double tolerance) {
  std::sort(values.begin(), values.end());
  std::vector<double> out;
  for (double v : values)
    if (out.empty() || std::abs(v - out.back()) > tolerance) out.push_back(v);
  return out;
}

std::vector<double> load_levels(std::vector<double> loads) {
  std::sort(loads.begin(), loads.end());
  std::vector<double> levels;
  if (loads.empty()) return levels;
  const double gap = kLoadLevelGap * std::abs(loads.back());
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < loads.size(); ++i) {
    if (i > 0 && loads[i] - loads[i - 1] > gap) {
      levels.push_back(sum / count);
      sum = 0;
      count = 0;
    }
    sum += loads[i];
    ++count;
  }
  levels.push_back(sum / count);
  return levels;
}

std::size_t nearest_level(double Fz, const std::vector<double>& levels) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < levels.size(); ++k)
    if (std::abs(Fz - levels[k]) < std::abs(Fz - levels[best])) best = k;
  return best;
}

std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  const double b = sxx > 0 ? sxy / sxx : 0.0;
  return {my - b * mx, b};
}

GroupPoints select_points(FitGroup group, std::span<const TyreTestPoint> points, bool with_camber) {
  constexpr double camber_tolerance = 1e-6;  // rad
  GroupPoints data;
  std::vector<double> loads;
  // Per inclination (rounded to the tolerance): how many slips of each sign.
  std::map<long long, std::pair<int, int>> signs_per_camber;
  bool negative = false, positive = false;
  for (const TyreTestPoint& p : points) {
    const double other_slip = group == FitGroup::pure_longitudinal ? p.alpha : p.kappa;
    if (std::abs(other_slip) > kPureSlipTolerance) continue;
    const bool cambered = std::abs(p.gamma) > camber_tolerance;
    if (cambered && (group == FitGroup::pure_longitudinal || !with_camber)) continue;
    data.points.push_back(p);
    loads.push_back(p.Fz);
    const double s = slip(group, p);
    auto& counts = signs_per_camber[std::llround(p.gamma / camber_tolerance)];
    counts.first += s < 0;
    counts.second += s > 0;
    negative = negative || s < 0;
    positive = positive || s > 0;
    data.peak = std::max(data.peak, std::abs(measured(group, p)));
  }
  data.loads = load_levels(loads);
  std::vector<char> cambered_level(data.loads.size(), 0);
  for (const TyreTestPoint& p : data.points)
    if (std::abs(p.gamma) > camber_tolerance) cambered_level[nearest_level(p.Fz, data.loads)] = 1;
  data.camber_point_levels = static_cast<int>(std::count(cambered_level.begin(), cambered_level.end(), 1));
  bool negative_camber = false, positive_camber = false;
  for (const auto& [gamma, counts] : signs_per_camber) {
    if (counts.first < 2 || counts.second < 2) continue;  // a sweep has at least 2 slips of each sign
    ++data.camber_sweeps;
    negative_camber = negative_camber || gamma < 0;
    positive_camber = positive_camber || gamma > 0;
  }
  data.camber_both_signs = negative_camber && positive_camber;
  data.both_signs = negative && positive;
  return data;
}

double LogBounded::value(double v) const {
  const double a = std::log(lo), b = std::log(hi);
  return std::exp(a + 0.5 * (b - a) * (1.0 + std::tanh(v)));
}

double LogBounded::result(double v) const {
  const double x = std::clamp(value(v), lo, hi);
  for (const double bound : {lo, hi})
    if (std::abs(x - bound) <= 1e-9 * bound) return bound;
  return x;
}

double LogBounded::parameter(double x) const {
  const double a = std::log(lo), b = std::log(hi);
  return std::atanh(std::clamp(2.0 * (std::log(x) - a) / (b - a) - 1.0, -0.99, 0.99));
}

}  // namespace tirefem::magic_formula_fit
