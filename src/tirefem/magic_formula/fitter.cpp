#include "tirefem/magic_formula/fitter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Core>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "tirefem/magic_formula/fit_points.hpp"
#include "tirefem/magic_formula/fit_start_values.hpp"

namespace tirefem {
namespace {

using namespace magic_formula_fit;
using M = MagicFormulaCoefficients;
using Member = double M::*;

// friction: a peak friction coefficient D/Fz (PDX1, PDY1) within [0.5, 1.25] × the largest |F|/Fz of the
// data. Without it, data that approach their friction limit without a peak (a Coulomb tread: F → μ Fz as the
// slip grows) are fitted as well by a far larger D with a small C, which extrapolates badly.
// peak_load: PKY2, the load (× FNOMIN) at which the cornering stiffness peaks, within [0.5, 4]. Loads well
// below the peak determine only PKY1/PKY2 (Kyα ≈ 2 PKY1 Fz/PKY2, linear in Fz), not each; public files
// have 1.4–2.
enum class Bound { free, positive, at_most_one, friction, peak_load };

// What a coefficient needs from the data to be determined. The shifts (PHX*, PVX*, PHY*, PVY*, QHZ*) need
// slips of both signs: on one side a horizontal and a vertical shift trade against each other and the
// curve's slope and curvature. Fitted to the example tyre's α sweep from 0 to 10° (64 × 12, 2000 N), they
// came out as PHY1 −0.0088 and PVY1 −0.11, which nearly cancel at α = 0 and make the file's Fy(−6°)
// +774 N against −1183 N at +6°, a symmetric tyre turned lopsided.
struct FittedCoefficient {
  const char* key;
  Member member;
  Bound bound = Bound::free;
  int loads = 1;                   // distinct loads needed
  int cambers = 1;                 // slip sweeps at distinct inclinations needed (gamma = 0 counts)
  bool both_signs = false;         // slips of both signs needed
  bool nominal = false;            // fitted in the first pass
  bool never = false;              // never fitted (see fitter.hpp)
  bool camber_both_signs = false;  // sweeps at a positive and a negative inclination needed (|gamma| beside gamma)
  // Cambered points at `loads` load levels suffice, free rolling ones too (no sweep needed): the shift of
  // the curve with camber, PVY3-4 (camber thrust at alpha = 0) and QDZ8-9 (the residual moment's).
  bool camber_points = false;
};

#define COEF(name, ...) FittedCoefficient{#name, &M::name, __VA_ARGS__}
constexpr Bound F = Bound::free;

const std::vector<FittedCoefficient>& group_coefficients(FitGroup group) {
  static const std::vector<FittedCoefficient> longitudinal{
      COEF(PCX1, Bound::positive, 1, 1, false, true), COEF(PDX1, Bound::friction, 1, 1, false, true),
      COEF(PDX2, F, 2), COEF(PDX3, F, 1, 2),
      COEF(PEX1, Bound::at_most_one, 1, 1, false, true), COEF(PEX2, F, 2), COEF(PEX3, F, 3),
      COEF(PEX4, F, 1, 1, true),
      COEF(PKX1, F, 1, 1, false, true), COEF(PKX2, F, 2), COEF(PKX3, F, 3),
      COEF(PHX1, F, 1, 1, true), COEF(PHX2, F, 2, 1, true), COEF(PVX1, F, 1, 1, true), COEF(PVX2, F, 2, 1, true)};
  static const std::vector<FittedCoefficient> lateral{
      COEF(PCY1, Bound::positive, 1, 1, false, true), COEF(PDY1, Bound::friction, 1, 1, false, true),
      COEF(PDY2, F, 2), COEF(PDY3, F, 1, 2),
      COEF(PEY1, Bound::at_most_one, 1, 1, false, true), COEF(PEY2, F, 2), COEF(PEY3, F, 1, 1, true),
      COEF(PEY4, F, 1, 2, true),
      COEF(PKY1, F, 1, 1, false, true), COEF(PKY2, Bound::peak_load, 2), COEF(PKY3, F, 1, 2),
      COEF(PHY1, F, 1, 1, true), COEF(PHY2, F, 2, 1, true), COEF(PHY3, F, 1, 2),
      COEF(PVY1, F, 1, 1, true), COEF(PVY2, F, 2, 1, true), COEF(PVY3, F, 1, 1, false, false, false, false, true),
      COEF(PVY4, F, 2, 1, false, false, false, false, true)};
  static const std::vector<FittedCoefficient> aligning{
      COEF(QBZ1, F, 1, 1, false, true), COEF(QBZ2, F, 2), COEF(QBZ3, F, 3), COEF(QBZ4, F, 1, 2),
      COEF(QBZ5, F, 1, 2, false, false, false, true), COEF(QBZ9, F, 1), COEF(QBZ10, F, 1, 1, false, false, true),
      COEF(QCZ1, Bound::positive, 1, 1, false, true),
      COEF(QDZ1, F, 1, 1, false, true), COEF(QDZ2, F, 2), COEF(QDZ3, F, 1, 2), COEF(QDZ4, F, 1, 3),
      COEF(QDZ6, F, 1), COEF(QDZ7, F, 2), COEF(QDZ8, F, 1, 1, false, false, false, false, true),
      COEF(QDZ9, F, 2, 1, false, false, false, false, true),
      COEF(QEZ1, Bound::at_most_one, 1, 1, false, true), COEF(QEZ2, F, 2), COEF(QEZ3, F, 3),
      COEF(QEZ4, F, 1, 1, true), COEF(QEZ5, F, 1, 2, true),
      COEF(QHZ1, F, 1, 1, true), COEF(QHZ2, F, 2, 1, true), COEF(QHZ3, F, 1, 2), COEF(QHZ4, F, 2, 2)};
  switch (group) {
    case FitGroup::pure_longitudinal: return longitudinal;
    case FitGroup::pure_lateral: return lateral;
    case FitGroup::aligning: return aligning;
  }
  return longitudinal;
}
#undef COEF

bool is_camber_term(const FittedCoefficient& f) { return f.cambers > 1 || f.camber_points; }

// The curvature factor E = (E1 + E2 dfz + E3 dfz^2)(1 - (E4 + E5 gamma) sgn(slip)) (4.E14, 4.E24) is a
// product of coefficients: with PEY1 = 0.004 and PEY3 = 41.5 the factors are badly scaled and their valley
// in the least-squares function is curved. The fit therefore uses the curvature on each side,
// E+ = E1 (1 - E4) and E- = E1 (1 + E4), the load ratios q2 = E2/E1, q3 = E3/E1 and the camber slope
// g = E1 E5: E = (1 + q2 dfz + q3 dfz^2)(E+- -+ g gamma), linear in each. Back: E1 = (E+ + E-)/2,
// E4 = (E- - E+)/(E+ + E-), E2 = q2 E1, E3 = q3 E1, E5 = g/E1. (E1 = 0 with E4 != 0 is the formula's own
// singularity: E+ = -E- is not representable.)
struct CurvatureTerms {
  Member e1, e2, e3, e4, e5;  // e3, e5 may be nullptr
};

const CurvatureTerms* curvature_terms(FitGroup group) {
  static const CurvatureTerms longitudinal{&M::PEX1, &M::PEX2, &M::PEX3, &M::PEX4, nullptr};
  static const CurvatureTerms lateral{&M::PEY1, &M::PEY2, nullptr, &M::PEY3, &M::PEY4};
  if (group == FitGroup::pure_longitudinal) return &longitudinal;
  if (group == FitGroup::pure_lateral) return &lateral;
  return nullptr;
}

enum class Role { plain, e_plus, e_minus, e_single, load_ratio, load_ratio_squared, camber_slope };

struct Parameter {
  Role role = Role::plain;
  Member member = nullptr;  // plain
  Bound bound = Bound::free;
  double lower = 0, upper = 0;  // Bound::friction
};

double to_parameter(const Parameter& p, double value) {
  switch (p.bound) {
    case Bound::positive: return std::log(std::max(value, 1e-6));
    case Bound::at_most_one: return std::log(std::max(1.0 - value, 1e-6));
    case Bound::friction:
    case Bound::peak_load: {
      const double t = std::clamp((value - p.lower) / (p.upper - p.lower), 1e-6, 1 - 1e-6);
      return std::log(t / (1 - t));
    }
    case Bound::free: return value;
  }
  return value;
}

double from_parameter(const Parameter& p, double u) {
  switch (p.bound) {
    case Bound::positive: return std::exp(u);
    case Bound::at_most_one: return 1.0 - std::exp(u);
    case Bound::friction:
    case Bound::peak_load: return p.lower + (p.upper - p.lower) / (1 + std::exp(-u));
    case Bound::free: return u;
  }
  return u;
}

// The parameter vector of one pass over the given coefficients.
std::vector<Parameter> parameters_for(FitGroup group, const GroupPoints& data,
                                      const std::vector<const FittedCoefficient*>& unknowns) {
  const CurvatureTerms* e = curvature_terms(group);
  double friction = 0;  // the largest |F|/Fz of the data
  for (const TyreTestPoint& p : data.points)
    if (p.Fz > 0) friction = std::max(friction, std::abs(measured(group, p)) / p.Fz);
  auto has = [&](Member m) {
    return m != nullptr && std::any_of(unknowns.begin(), unknowns.end(), [&](auto* f) { return f->member == m; });
  };
  std::vector<Parameter> out;
  for (const FittedCoefficient* f : unknowns) {
    const bool curvature = e != nullptr && (f->member == e->e1 || f->member == e->e2 || f->member == e->e3 ||
                                            f->member == e->e4 || f->member == e->e5);
    if (curvature) continue;
    if (f->bound == Bound::peak_load) out.push_back({Role::plain, f->member, f->bound, 0.5, 4.0});
    else out.push_back({Role::plain, f->member, f->bound, 0.5 * friction, 1.25 * friction});
  }
  if (e == nullptr || !has(e->e1)) return out;
  if (has(e->e4)) {
    out.push_back({Role::e_plus, nullptr, Bound::at_most_one});
    out.push_back({Role::e_minus, nullptr, Bound::at_most_one});
  } else {
    out.push_back({Role::e_single, nullptr, Bound::at_most_one});
  }
  if (has(e->e2)) out.push_back({Role::load_ratio});
  if (has(e->e3)) out.push_back({Role::load_ratio_squared});
  if (has(e->e5)) out.push_back({Role::camber_slope});
  return out;
}

Eigen::VectorXd initial_parameters(FitGroup group, const std::vector<Parameter>& parameters, const M& c) {
  const CurvatureTerms* e = curvature_terms(group);
  Eigen::VectorXd u(static_cast<Eigen::Index>(parameters.size()));
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const Parameter& p = parameters[i];
    double value = 0;
    if (p.role == Role::plain) {
      value = c.*(p.member);
    } else {
      const double E1 = c.*(e->e1), E4 = c.*(e->e4);
      switch (p.role) {
        case Role::e_plus: value = E1 * (1 - E4); break;
        case Role::e_minus: value = E1 * (1 + E4); break;
        case Role::e_single: value = E1; break;
        case Role::load_ratio: value = E1 != 0 ? c.*(e->e2) / E1 : 0.0; break;
        case Role::load_ratio_squared: value = E1 != 0 ? c.*(e->e3) / E1 : 0.0; break;
        case Role::camber_slope: value = E1 * c.*(e->e5); break;
        case Role::plain: break;
      }
    }
    u[static_cast<Eigen::Index>(i)] = to_parameter(p, value);
  }
  return u;
}

void apply_parameters(FitGroup group, const std::vector<Parameter>& parameters, const Eigen::VectorXd& u, M& c) {
  const CurvatureTerms* e = curvature_terms(group);
  double e_plus = 0, e_minus = 0, e_single = 0, q2 = 0, q3 = 0, g = 0;
  bool split = false, single = false, load = false, load_squared = false, camber = false;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const Parameter& p = parameters[i];
    const double value = from_parameter(p, u[static_cast<Eigen::Index>(i)]);
    switch (p.role) {
      case Role::plain: c.*(p.member) = value; break;
      case Role::e_plus: e_plus = value, split = true; break;
      case Role::e_minus: e_minus = value; break;
      case Role::e_single: e_single = value, single = true; break;
      case Role::load_ratio: q2 = value, load = true; break;
      case Role::load_ratio_squared: q3 = value, load_squared = true; break;
      case Role::camber_slope: g = value, camber = true; break;
    }
  }
  if (e == nullptr || !(split || single)) return;
  const double E1 = split ? 0.5 * (e_plus + e_minus) : e_single;
  c.*(e->e1) = E1;
  if (split) c.*(e->e4) = E1 != 0 ? (e_minus - e_plus) / (2 * E1) : 0.0;
  if (load) c.*(e->e2) = q2 * E1;
  if (load_squared) c.*(e->e3) = q3 * E1;
  if (camber) c.*(e->e5) = E1 != 0 ? g / E1 : 0.0;
}

struct ResidualFunctor {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  FitGroup group;
  const GroupPoints* data;
  std::vector<Parameter> parameters;
  M base;

  int inputs() const { return static_cast<int>(parameters.size()); }
  int values() const { return static_cast<int>(data->points.size()); }

  M coefficients(const Eigen::VectorXd& u) const {
    M c = base;
    apply_parameters(group, parameters, u, c);
    return c;
  }

  // Residuals relative to the channel's peak.
  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& residual) const {
    const M c = coefficients(u);
    for (std::size_t i = 0; i < data->points.size(); ++i) {
      const TyreTestPoint& p = data->points[i];
      residual[static_cast<Eigen::Index>(i)] = (model(group, c, p) - measured(group, p)) / data->peak;
    }
    return 0;
  }
};

bool converged_status(Eigen::LevenbergMarquardtSpace::Status status) {
  using namespace Eigen::LevenbergMarquardtSpace;
  return status == RelativeReductionTooSmall || status == RelativeErrorTooSmall ||
         status == RelativeErrorAndReductionTooSmall || status == FtolTooSmall || status == XtolTooSmall ||
         status == CosinusTooSmall;
}

// One Levenberg-Marquardt solve. Central differences with the step eps^(1/3)|u| (epsfcn = eps^(2/3)): the
// Jacobian to ~1e-11, whose error slows the last iterations a little but does not move the solution (for
// noise-free data the residual is zero there). Column scaling (Eigen's mode 1) from the Jacobian's norms.
int run_levenberg_marquardt(FitGroup group, const GroupPoints& data, const std::vector<const FittedCoefficient*>& unknowns,
                            M& c, bool& converged) {
  ResidualFunctor functor{group, &data, parameters_for(group, data, unknowns), c};
  Eigen::VectorXd u = initial_parameters(group, functor.parameters, c);
  using Numerical = Eigen::NumericalDiff<ResidualFunctor, Eigen::Central>;
  Numerical numerical(functor, 3.7e-11);
  Eigen::LevenbergMarquardt<Numerical> lm(numerical);
  lm.parameters.ftol = 1e-15;
  lm.parameters.xtol = 1e-15;
  lm.parameters.maxfev = 2000;
  const auto status = lm.minimize(u);
  converged = converged_status(status);
  c = functor.coefficients(u);
  return static_cast<int>(lm.nfev + lm.njev * (2 * functor.inputs()));
}

// The least-squares function of a curve without a peak (a Coulomb tread saturating at mu Fz) has more than
// one minimum: a large D with C < 1 and E < 0, or a D near the largest |F|/Fz with C > 1 and E near 0.
// Which one Levenberg-Marquardt finds from the data's start values changed with 0.09% changes of the rig's
// lateral forces (PKY1 -24.0 or -26.9, PDY1 0.85 or 0.67, Fy RMS 0.57% or 1.02% of the peak); a start
// from C 0.7 times lower finds the better one in both. The shape factor's start is scaled by each of these.
constexpr double kShapeFactorStarts[] = {1.0, 0.7, 1.4};
// A fit whose shape factor ends above this (the force or trail changes sign at large slip; a start from C
// twice the data's found QCZ1 = 745 with QBZ1 = 2764) is kept only when no start gives a plausible one.
constexpr double kMaxPlausibleShapeFactor = 2.0;

Member shape_factor_of(FitGroup group) {
  switch (group) {
    case FitGroup::pure_longitudinal: return &M::PCX1;
    case FitGroup::pure_lateral: return &M::PCY1;
    case FitGroup::aligning: return &M::QCZ1;
  }
  return &M::PCX1;
}

const char* channel_name(FitGroup group) {
  return group == FitGroup::pure_longitudinal ? "Fx" : (group == FitGroup::pure_lateral ? "Fy" : "Mz");
}

}  // namespace

GroupFitResult fit_coefficient_group(FitGroup group, std::span<const TyreTestPoint> points,
                                     MagicFormulaCoefficients& c) {
  const auto start_time = std::chrono::steady_clock::now();
  const GroupPoints pure = select_points(group, points, false);
  const GroupPoints all = select_points(group, points, true);
  GroupFitResult result;
  result.group = group;

  std::vector<const FittedCoefficient*> nominal, uncambered, determined;
  for (const FittedCoefficient& f : group_coefficients(group)) {
    const GroupPoints& data = is_camber_term(f) ? all : pure;
    const bool ok = !f.never && static_cast<int>(data.loads.size()) >= f.loads &&
                    (!is_camber_term(f) || f.camber_points || all.camber_sweeps >= f.cambers) && (!f.both_signs || data.both_signs) &&
                    (!f.camber_both_signs || all.camber_both_signs) &&
                    (!f.camber_points || all.camber_point_levels >= f.loads);
    (ok ? result.fitted : result.not_determined).emplace_back(f.key);
    c.*(f.member) = 0;  // neutral value (every coefficient of the three groups is 0 when neutral)
    if (!ok) continue;
    determined.push_back(&f);
    if (!is_camber_term(f)) uncambered.push_back(&f);
    if (f.nominal) nominal.push_back(&f);
  }
  if (all.points.size() < determined.size() + 1 || all.peak == 0)
    throw std::invalid_argument(fmt::format("Magic Formula fit of {}: {} usable points for {} coefficients",
                                            channel_name(group), all.points.size(), determined.size()));

  set_start_values(group, pure, c);
  // The start values of coefficients left out stay out: neutral, but for PKY2, which divides Fz (its start
  // value serves as the assumed one).
  for (const FittedCoefficient& f : group_coefficients(group))
    if (f.member != &M::PKY2 &&
        std::find(result.not_determined.begin(), result.not_determined.end(), f.key) != result.not_determined.end())
      c.*(f.member) = 0;
  const M start = c;
  const Member shape = shape_factor_of(group);
  int evaluations = 0;
  bool converged = false;
  double sum = std::numeric_limits<double>::infinity();
  bool plausible = false;
  // Starts: the shape factor C from the data, and scaled down and up (kShapeFactorStarts). Of the fits
  // with a plausible C, the one with the least sum of squares is kept (the first of equal ones).
  for (double scale : kShapeFactorStarts) {
    M trial = start;
    trial.*shape *= scale;
    bool trial_converged = false;
    // Passes: the nominal-load coefficients, then all without camber on the gamma = 0 points, then (with
    // camber sweeps) all on all points.
    evaluations += run_levenberg_marquardt(group, pure, nominal, trial, trial_converged);
    evaluations += run_levenberg_marquardt(group, pure, uncambered, trial, trial_converged);
    if (determined.size() > uncambered.size())
      evaluations += run_levenberg_marquardt(group, all, determined, trial, trial_converged);
    double trial_sum = 0;
    for (const TyreTestPoint& p : all.points) trial_sum += std::pow(model(group, trial, p) - measured(group, p), 2);
    const bool trial_plausible = trial.*shape <= kMaxPlausibleShapeFactor;
    if (plausible && !trial_plausible) continue;
    if (plausible == trial_plausible && !(trial_sum < sum)) continue;
    sum = trial_sum;
    plausible = trial_plausible;
    c = trial;
    converged = trial_converged;
  }
  result.error.channel = channel_name(group);
  result.error.points = static_cast<int>(all.points.size());
  result.error.rms = std::sqrt(sum / static_cast<double>(all.points.size()));
  result.error.peak = all.peak;
  result.error.relative_rms = result.error.rms / all.peak;
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
