#include "tirefem/magic_formula/combined_slip_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "tirefem/magic_formula/evaluator.hpp"
#include "tirefem/magic_formula/fit_points.hpp"

namespace tirefem {
namespace {

using M = MagicFormulaCoefficients;
using Member = double M::*;

constexpr const char* kKeys[] = {"RBX1", "RBX2", "RCX1", "REX1", "REX2", "RHX1", "RBY1", "RBY2",
                                 "RBY3", "RCY1", "REY1", "REY2", "RHY1", "RHY2", "RVY1", "RVY2",
                                 "RVY3", "RVY4", "RVY5", "RVY6", "SSZ1", "SSZ2", "SSZ3", "SSZ4"};

// The weighting function of one force, G = cos(C atan(B s)) in the other slip s with B = B1 cos(atan(B2 s')):
// its slope factor B1 (within kSlope) and shape C (within kShape) need two levels of s (|alpha| for Fx, |kappa| for Fy),
// the slope's fall B2 with the force's own slip s' two levels of that too.
struct Weighting {
  const char* name;  // channel
  Member slope, slope_fall, shape;
  const char *slope_key, *slope_fall_key, *shape_key;
  bool longitudinal;
};
constexpr Weighting kWeightings[] = {
    {"Fx combined", &M::RBX1, &M::RBX2, &M::RCX1, "RBX1", "RBX2", "RCX1", true},
    {"Fy combined", &M::RBY1, &M::RBY2, &M::RCY1, "RBY1", "RBY2", "RCY1", false}};

// Bounds (LogBounded): with small slips only the product C B is determined, and unbounded the fit of the
// smoke test's rig (|kappa| <= 0.03, alpha <= 3°) ran to RBX1 9e-7 and RCX1 1.8e7, a G that turns negative
// at 5.4°; bounded by 2 it took C = 2, negative beyond B s = 1 (6.5°). G = cos(C atan(B s)) stays >= 0
// for C <= 1 and turns negative only beyond B s = tan(pi / 2C), 3.7 at C = 1.2. Public passenger-tyre
// files have RBX1 12-15, RBY1 5.5-7, RCX1 and RCY1 1.0-1.13.
constexpr magic_formula_fit::LogBounded kSlope{1.0, 50.0};
constexpr magic_formula_fit::LogBounded kShape{0.5, 1.2};

// Starts of the slope factor B1 (B2 from the same value, C 1): public passenger-tyre files have RBX1
// 12-13, RBY1 6-7; a grid of a few slips may sit on either side of the minimum.
constexpr double kSlopeStarts[] = {5.0, 10.0, 20.0};

struct Residual {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const Weighting* w;
  const std::vector<TyreTestPoint>* points;
  M base;
  double peak;
  bool with_fall;  // B2 fitted (else held at 0)

  int inputs() const { return with_fall ? 3 : 2; }
  int values() const { return static_cast<int>(points->size()); }
  M coefficients(const Eigen::VectorXd& u) const {
    M c = base;
    c.*(w->slope) = kSlope.value(u[0]);
    c.*(w->shape) = kShape.value(u[1]);
    c.*(w->slope_fall) = with_fall ? u[2] : 0.0;
    return c;
  }
  double model(const M& c, const TyreTestPoint& p) const {
    const auto f = evaluate_magic_formula(c, {p.Fz, p.kappa, p.alpha, 0.0}, SlipCombination::combined);
    return w->longitudinal ? f.Fx : f.Fy;
  }
  double measured(const TyreTestPoint& p) const { return w->longitudinal ? p.Fx : p.Fy; }
  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& r) const {
    const M c = coefficients(u);
    for (std::size_t i = 0; i < points->size(); ++i)
      r[static_cast<Eigen::Index>(i)] = (model(c, (*points)[i]) - measured((*points)[i])) / peak;
    return 0;
  }
};

}  // namespace

std::span<const char* const> combined_slip_keys() { return kKeys; }

CombinedSlipFit fit_combined_slip(std::span<const TyreTestPoint> all, MagicFormulaCoefficients& c) {
  CombinedSlipFit out;
  std::vector<TyreTestPoint> points;
  for (const TyreTestPoint& p : all)
    if (std::abs(p.kappa) > magic_formula_fit::kPureSlipTolerance &&
        std::abs(p.alpha) > magic_formula_fit::kPureSlipTolerance && p.gamma == 0)
      points.push_back(p);
  for (const char* key : kKeys) c.*(find_coefficient(key)->member) = find_coefficient(key)->neutral;
  const auto levels = [&](bool kappa) {
    std::vector<double> v;
    for (const TyreTestPoint& p : points) v.push_back(std::abs(kappa ? p.kappa : p.alpha));
    return magic_formula_fit::distinct_values(v, 1e-9).size();
  };
  const std::size_t kappa_levels = levels(true), alpha_levels = levels(false);
  for (const Weighting& w : kWeightings) {
    const std::size_t other = w.longitudinal ? alpha_levels : kappa_levels, own = w.longitudinal ? kappa_levels : alpha_levels;
    if (other < 2) continue;
    Residual f{&w, &points, c, 0.0, own >= 2};
    if (points.size() <= static_cast<std::size_t>(f.inputs())) continue;
    for (const TyreTestPoint& p : points) f.peak = std::max(f.peak, std::abs(f.measured(p)));
    if (!(f.peak > 0)) continue;
    double best = std::numeric_limits<double>::infinity();
    Eigen::VectorXd best_u;
    for (double start : kSlopeStarts) {
      Eigen::VectorXd u(f.inputs());
      u[0] = kSlope.parameter(start);
      u[1] = kShape.parameter(1.0);
      if (f.with_fall) u[2] = start;
      Eigen::NumericalDiff<Residual, Eigen::Central> numerical(f, 3.7e-11);
      Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residual, Eigen::Central>> lm(numerical);
      lm.parameters.ftol = lm.parameters.xtol = 1e-15;
      lm.parameters.maxfev = 2000;
      lm.minimize(u);
      Eigen::VectorXd r(f.values());
      f(u, r);
      if (u.allFinite() && r.squaredNorm() < best) best = r.squaredNorm(), best_u = u;
    }
    if (best_u.size() != f.inputs()) continue;
    c = f.coefficients(best_u);
    c.*(w.slope) = kSlope.result(best_u[0]);  // on a bound it ran into (LogBounded::result)
    c.*(w.shape) = kShape.result(best_u[1]);
    ChannelFitError e;
    e.channel = w.name;
    e.points = static_cast<int>(points.size());
    e.peak = f.peak;
    e.relative_rms = std::sqrt(best / static_cast<double>(points.size()));
    e.rms = e.relative_rms * f.peak;
    out.errors.push_back(e);
    out.fitted.insert(out.fitted.end(), {w.slope_key, w.shape_key});
    if (f.with_fall) out.fitted.emplace_back(w.slope_fall_key);
  }
  for (const char* key : kKeys)
    if (std::find(out.fitted.begin(), out.fitted.end(), key) == out.fitted.end()) out.not_determined.emplace_back(key);
  return out;
}

}  // namespace tirefem
