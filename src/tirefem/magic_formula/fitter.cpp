#include "tirefem/magic_formula/fitter.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "tirefem/magic_formula/evaluator.hpp"

namespace tirefem {
namespace {

using Member = double MagicFormulaCoefficients::*;

enum class Bound { free, positive, at_most_one };

// What a coefficient needs from the data to be determined.
struct FittedCoefficient {
  const char* key;
  Member member;
  Bound bound = Bound::free;
  int loads = 1;             // distinct loads needed
  int cambers = 1;           // distinct inclination angles needed
  bool both_signs = false;   // slips of both signs needed
  bool nominal = false;      // fitted in the first pass
  bool never = false;        // never fitted (see fitter.hpp)
};

using M = MagicFormulaCoefficients;
#define COEF(name, ...) FittedCoefficient{#name, &M::name, __VA_ARGS__}

const std::vector<FittedCoefficient>& group_coefficients(FitGroup group) {
  static const std::vector<FittedCoefficient> longitudinal{
      COEF(PCX1, Bound::positive, 1, 1, false, true), COEF(PDX1, Bound::positive, 1, 1, false, true),
      COEF(PDX2, Bound::free, 2),                      COEF(PDX3, Bound::free, 1, 2),
      COEF(PEX1, Bound::at_most_one, 1, 1, false, true), COEF(PEX2, Bound::free, 2),
      COEF(PEX3, Bound::free, 3),                      COEF(PEX4, Bound::free, 1, 1, true),
      COEF(PKX1, Bound::free, 1, 1, false, true),      COEF(PKX2, Bound::free, 2),
      COEF(PKX3, Bound::free, 3),                      COEF(PHX1, Bound::free, 1),
      COEF(PHX2, Bound::free, 2),                      COEF(PVX1, Bound::free, 1),
      COEF(PVX2, Bound::free, 2)};
  static const std::vector<FittedCoefficient> lateral{
      COEF(PCY1, Bound::positive, 1, 1, false, true), COEF(PDY1, Bound::positive, 1, 1, false, true),
      COEF(PDY2, Bound::free, 2),                      COEF(PDY3, Bound::free, 1, 3),
      COEF(PEY1, Bound::at_most_one, 1, 1, false, true), COEF(PEY2, Bound::free, 2),
      COEF(PEY3, Bound::free, 1, 1, true),             COEF(PEY4, Bound::free, 1, 2, true),
      COEF(PKY1, Bound::free, 1, 1, false, true),      COEF(PKY2, Bound::positive, 2),
      COEF(PKY3, Bound::free, 1, 2),                   COEF(PHY1, Bound::free, 1),
      COEF(PHY2, Bound::free, 2),                      COEF(PHY3, Bound::free, 1, 2),
      COEF(PVY1, Bound::free, 1),                      COEF(PVY2, Bound::free, 2),
      COEF(PVY3, Bound::free, 1, 2),                   COEF(PVY4, Bound::free, 2, 2)};
  static const std::vector<FittedCoefficient> aligning{
      COEF(QBZ1, Bound::free, 1, 1, false, true),      COEF(QBZ2, Bound::free, 2),
      COEF(QBZ3, Bound::free, 3),                      COEF(QBZ4, Bound::free, 1, 2),
      COEF(QBZ5, Bound::free, 1, 3),                   COEF(QBZ9, Bound::free, 1),
      COEF(QBZ10, Bound::free, 1, 1, false, false, true),
      COEF(QCZ1, Bound::positive, 1, 1, false, true),  COEF(QDZ1, Bound::free, 1, 1, false, true),
      COEF(QDZ2, Bound::free, 2),                      COEF(QDZ3, Bound::free, 1, 2),
      COEF(QDZ4, Bound::free, 1, 3),                   COEF(QDZ6, Bound::free, 1),
      COEF(QDZ7, Bound::free, 2),                      COEF(QDZ8, Bound::free, 1, 2),
      COEF(QDZ9, Bound::free, 2, 2),                   COEF(QEZ1, Bound::at_most_one, 1, 1, false, true),
      COEF(QEZ2, Bound::free, 2),                      COEF(QEZ3, Bound::free, 3),
      COEF(QEZ4, Bound::free, 1, 1, true),             COEF(QEZ5, Bound::free, 1, 2, true),
      COEF(QHZ1, Bound::free, 1),                      COEF(QHZ2, Bound::free, 2),
      COEF(QHZ3, Bound::free, 1, 2),                   COEF(QHZ4, Bound::free, 2, 2)};
  switch (group) {
    case FitGroup::pure_longitudinal: return longitudinal;
    case FitGroup::pure_lateral: return lateral;
    case FitGroup::aligning: return aligning;
  }
  return longitudinal;
}
#undef COEF

double to_parameter(Bound bound, double value) {
  switch (bound) {
    case Bound::positive: return std::log(std::max(value, 1e-6));
    case Bound::at_most_one: return std::log(std::max(1.0 - value, 1e-6));
    case Bound::free: return value;
  }
  return value;
}

double from_parameter(Bound bound, double u) {
  switch (bound) {
    case Bound::positive: return std::exp(u);
    case Bound::at_most_one: return 1.0 - std::exp(u);
    case Bound::free: return u;
  }
  return u;
}

// Distinct values within a relative tolerance (loads) or an absolute one (angles).
std::vector<double> distinct_values(std::vector<double> values, double tolerance) {
  std::sort(values.begin(), values.end());
  std::vector<double> out;
  for (double v : values)
    if (out.empty() || std::abs(v - out.back()) > tolerance) out.push_back(v);
  return out;
}

struct GroupData {
  std::vector<TyreTestPoint> points;
  std::vector<double> loads;  // distinct
  int camber_levels = 0;
  bool both_signs = false;
  double peak = 0;
};

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

GroupData select_points(FitGroup group, std::span<const TyreTestPoint> points) {
  GroupData data;
  constexpr double pure_tolerance = 1e-12;
  std::vector<double> loads, cambers;
  bool negative = false, positive = false;
  for (const TyreTestPoint& p : points) {
    const double other_slip = group == FitGroup::pure_longitudinal ? p.alpha : p.kappa;
    if (std::abs(other_slip) > pure_tolerance) continue;
    data.points.push_back(p);
    loads.push_back(p.Fz);
    cambers.push_back(p.gamma);
    negative = negative || slip(group, p) < 0;
    positive = positive || slip(group, p) > 0;
    data.peak = std::max(data.peak, std::abs(measured(group, p)));
  }
  const double max_load = loads.empty() ? 0.0 : *std::max_element(loads.begin(), loads.end());
  data.loads = distinct_values(loads, 1e-3 * max_load);
  data.camber_levels = static_cast<int>(distinct_values(cambers, 1e-6).size());
  data.both_signs = negative && positive;
  return data;
}

// Least-squares line y = a + b x (b = 0 with a single x).
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

struct LoadLevelFeatures {
  double dfz, Fz, peak, slope, trail;
};

// Per load: the peak |F|, the slope through the two slips nearest zero and the trail -Mz/Fy there.
std::vector<LoadLevelFeatures> load_level_features(FitGroup group, const GroupData& data, double Fz0) {
  std::vector<LoadLevelFeatures> out;
  for (double load : data.loads) {
    std::vector<const TyreTestPoint*> level;
    for (const TyreTestPoint& p : data.points)
      if (std::abs(p.Fz - load) <= 1e-3 * load) level.push_back(&p);
    std::sort(level.begin(), level.end(), [&](auto* a, auto* b) { return std::abs(slip(group, *a)) < std::abs(slip(group, *b)); });
    LoadLevelFeatures f{(load - Fz0) / Fz0, load, 0, 0, 0};
    for (auto* p : level) f.peak = std::max(f.peak, std::abs(group == FitGroup::pure_longitudinal ? p->Fx : p->Fy));
    if (level.size() >= 2) {
      const TyreTestPoint* a = level[0];
      const TyreTestPoint* b = level[1];
      for (std::size_t i = 1; i < level.size() && slip(group, *b) == slip(group, *a); ++i) b = level[i];
      const double ds = slip(group, *b) - slip(group, *a);
      if (ds != 0) f.slope = (measured(group == FitGroup::aligning ? FitGroup::pure_lateral : group, *b) -
                              measured(group == FitGroup::aligning ? FitGroup::pure_lateral : group, *a)) / ds;
    }
    for (auto* p : level)
      if (p->alpha != 0 && p->Fy != 0) {
        f.trail = -p->Mz / p->Fy;
        break;
      }
    out.push_back(f);
  }
  return out;
}

void set_start_values(FitGroup group, const GroupData& data, MagicFormulaCoefficients& c) {
  const double Fz0 = c.FNOMIN * c.LFZO;
  const auto levels = load_level_features(group, data, Fz0);
  std::vector<double> dfz, mu, stiffness, trail;
  for (const auto& l : levels) {
    dfz.push_back(l.dfz);
    mu.push_back(l.peak / l.Fz);
    stiffness.push_back(l.slope / l.Fz);
    trail.push_back(l.trail * Fz0 / (l.Fz * c.UNLOADED_RADIUS));
  }
  for (const FittedCoefficient& f : group_coefficients(group)) c.*(f.member) = 0;
  const auto [mu0, mu1] = fit_line(dfz, mu);
  if (group == FitGroup::pure_longitudinal) {
    const auto [k0, k1] = fit_line(dfz, stiffness);
    c.PCX1 = 1.6;
    c.PDX1 = std::max(mu0, 0.1) / c.LMUX;
    c.PDX2 = mu1 / c.LMUX;
    c.PKX1 = k0 / c.LKX;
    c.PKX2 = k1 / c.LKX;
  } else if (group == FitGroup::pure_lateral) {
    c.PCY1 = 1.3;
    c.PDY1 = std::max(mu0, 0.1) / c.LMUY;
    c.PDY2 = mu1 / c.LMUY;
    c.PKY2 = 1.5;
    double sum = 0;
    for (const auto& l : levels) sum += l.slope / (Fz0 * std::sin(2 * std::atan(l.Fz / (c.PKY2 * Fz0))) * c.LKY);
    c.PKY1 = sum / static_cast<double>(levels.size());
  } else {
    const auto [t0, t1] = fit_line(dfz, trail);
    c.QBZ1 = 10;
    c.QCZ1 = 1.2;
    c.QDZ1 = t0 / c.LTR;
    c.QBZ9 = 10;
  }
}

struct ResidualFunctor {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  FitGroup group;
  const GroupData* data;
  std::vector<const FittedCoefficient*> unknowns;
  MagicFormulaCoefficients base;

  int inputs() const { return static_cast<int>(unknowns.size()); }
  int values() const { return static_cast<int>(data->points.size()); }

  MagicFormulaCoefficients coefficients(const Eigen::VectorXd& u) const {
    MagicFormulaCoefficients c = base;
    for (std::size_t i = 0; i < unknowns.size(); ++i)
      c.*(unknowns[i]->member) = from_parameter(unknowns[i]->bound, u[static_cast<Eigen::Index>(i)]);
    return c;
  }

  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& residual) const {
    const MagicFormulaCoefficients c = coefficients(u);
    for (std::size_t i = 0; i < data->points.size(); ++i) {
      const TyreTestPoint& p = data->points[i];
      residual[static_cast<Eigen::Index>(i)] = (model(group, c, p) - measured(group, p)) / data->peak;
    }
    return 0;
  }
};

int run_levenberg_marquardt(ResidualFunctor& functor, MagicFormulaCoefficients& c, bool& converged) {
  Eigen::VectorXd u(functor.inputs());
  for (std::size_t i = 0; i < functor.unknowns.size(); ++i)
    u[static_cast<Eigen::Index>(i)] = to_parameter(functor.unknowns[i]->bound, c.*(functor.unknowns[i]->member));
  Eigen::NumericalDiff<ResidualFunctor, Eigen::Central> numerical(functor);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<ResidualFunctor, Eigen::Central>> lm(numerical);
  lm.parameters.ftol = 1e-15;
  lm.parameters.xtol = 1e-15;
  lm.parameters.maxfev = 4000;
  const auto status = lm.minimize(u);
  converged = status == Eigen::LevenbergMarquardtSpace::RelativeReductionTooSmall ||
              status == Eigen::LevenbergMarquardtSpace::RelativeErrorTooSmall ||
              status == Eigen::LevenbergMarquardtSpace::RelativeErrorAndReductionTooSmall ||
              status == Eigen::LevenbergMarquardtSpace::FtolTooSmall ||
              status == Eigen::LevenbergMarquardtSpace::XtolTooSmall ||
              status == Eigen::LevenbergMarquardtSpace::CosinusTooSmall;
  c = functor.coefficients(u);
  return static_cast<int>(lm.nfev + lm.njev * (2 * functor.inputs()));
}

const char* channel_name(FitGroup group) {
  return group == FitGroup::pure_longitudinal ? "Fx" : (group == FitGroup::pure_lateral ? "Fy" : "Mz");
}

}  // namespace

GroupFitResult fit_coefficient_group(FitGroup group, std::span<const TyreTestPoint> points,
                                     MagicFormulaCoefficients& c) {
  const auto start_time = std::chrono::steady_clock::now();
  const GroupData data = select_points(group, points);
  GroupFitResult result;
  result.group = group;

  std::vector<const FittedCoefficient*> determined, nominal;
  for (const FittedCoefficient& f : group_coefficients(group)) {
    const bool ok = !f.never && static_cast<int>(data.loads.size()) >= f.loads && data.camber_levels >= f.cambers &&
                    (!f.both_signs || data.both_signs);
    (ok ? result.fitted : result.not_determined).emplace_back(f.key);
    if (ok) determined.push_back(&f);
    if (ok && f.nominal) nominal.push_back(&f);
  }
  if (data.points.size() < determined.size() + 1 || data.peak == 0)
    throw std::invalid_argument(fmt::format("Magic Formula fit of {}: {} usable points for {} coefficients",
                                            channel_name(group), data.points.size(), determined.size()));

  set_start_values(group, data, c);
  int evaluations = 0;
  bool converged = false;
  for (const auto* unknowns : {&nominal, &determined}) {
    ResidualFunctor functor{{}, {}, {}, {}};
    functor.group = group;
    functor.data = &data;
    functor.unknowns = *unknowns;
    functor.base = c;
    evaluations += run_levenberg_marquardt(functor, c, converged);
  }

  double sum = 0;
  for (const TyreTestPoint& p : data.points) sum += std::pow(model(group, c, p) - measured(group, p), 2);
  result.error.channel = channel_name(group);
  result.error.points = static_cast<int>(data.points.size());
  result.error.rms = std::sqrt(sum / static_cast<double>(data.points.size()));
  result.error.peak = data.peak;
  result.error.relative_rms = result.error.rms / data.peak;
  result.function_evaluations = evaluations;
  result.converged = converged;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return result;
}

MagicFormulaFit fit_magic_formula(std::span<const TyreTestPoint> points, const MagicFormulaCoefficients& start) {
  MagicFormulaFit fit{start, {}};
  for (FitGroup group : {FitGroup::pure_longitudinal, FitGroup::pure_lateral, FitGroup::aligning})
    fit.groups.push_back(fit_coefficient_group(group, points, fit.coefficients));
  return fit;
}

}  // namespace tirefem
