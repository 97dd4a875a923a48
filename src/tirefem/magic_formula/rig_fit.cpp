#include "tirefem/magic_formula/rig_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "tirefem/magic_formula/evaluator.hpp"
#include "tirefem/magic_formula/fit_points.hpp"

namespace tirefem {
namespace {

// Mx = R0 Fz (QSX1 - QSX2 gamma + QSX3 Fy/Fz0') (4.E69) with the model's pure-slip Fy: linear least squares.
ChannelFitError fit_overturning_moment(const std::vector<RigPoint>& points, MagicFormulaCoefficients& c,
                                       std::vector<std::string>& not_determined) {
  std::vector<const RigPoint*> used;
  bool cambered = false, cornering = false;
  for (const RigPoint& p : points)
    if (std::abs(p.KAPPA) <= magic_formula_fit::kPureSlipTolerance) {
      used.push_back(&p);
      cambered = cambered || p.GAMMA != 0;
      cornering = cornering || p.ALPHA != 0;
    }
  c.QSX1 = c.QSX2 = c.QSX3 = 0;
  if (!cambered) not_determined.emplace_back("QSX2");
  if (!cornering) not_determined.emplace_back("QSX3");
  const int columns = 1 + cambered + cornering;
  const double R0 = c.UNLOADED_RADIUS, Fz0 = c.FNOMIN * c.LFZO;
  Eigen::MatrixXd A(static_cast<Eigen::Index>(used.size()), columns);
  Eigen::VectorXd b(static_cast<Eigen::Index>(used.size()));
  for (std::size_t i = 0; i < used.size(); ++i) {
    const RigPoint& p = *used[i];
    const double Fy = pure_lateral_force(c, p.FZ, p.ALPHA, p.GAMMA).Fy0;
    const auto row = static_cast<Eigen::Index>(i);
    int k = 0;
    A(row, k++) = R0 * p.FZ * c.LVMX * c.LMX;
    if (cambered) A(row, k++) = -R0 * p.FZ * p.GAMMA * c.LMX;
    if (cornering) A(row, k++) = R0 * p.FZ * Fy / Fz0 * c.LMX;
    b[row] = p.MX;
  }
  ChannelFitError e;
  e.channel = "Mx";
  e.points = static_cast<int>(used.size());
  if (used.empty()) return e;
  const Eigen::VectorXd q = A.colPivHouseholderQr().solve(b);
  int k = 0;
  c.QSX1 = q[k++];
  if (cambered) c.QSX2 = q[k++];
  if (cornering) c.QSX3 = q[k++];
  e.rms = std::sqrt((A * q - b).squaredNorm() / static_cast<double>(used.size()));
  e.peak = b.cwiseAbs().maxCoeff();
  e.relative_rms = e.peak > 0 ? e.rms / e.peak : 0.0;
  return e;
}

}  // namespace

std::span<const NeverDetermined> never_determined_by_the_rig() {
  using enum UndeterminedReason;
  static constexpr NeverDetermined keys[] = {
      {"QSY1", rolling_resistance}, {"QSY2", rolling_resistance}, {"QSY3", rolling_resistance},
      {"QSY4", rolling_resistance}, {"VERTICAL_DAMPING", steady_state}, {"Q_V1", steady_state},
      {"Q_V2", steady_state}, {"Q_FCX", steady_state}, {"Q_FCY", steady_state}, {"QTZ1", steady_state},
      {"MBELT", steady_state}};
  return keys;
}

RigFit fit_rig_data(const RigData& data) {
  const auto start_time = std::chrono::steady_clock::now();
  if (!(data.FNOMIN > 0) || !(data.UNLOADED_RADIUS > 0))
    throw std::invalid_argument("Magic Formula rig fit: FNOMIN and UNLOADED_RADIUS must be positive");
  RigFit fit;
  fit.coefficients.FNOMIN = data.FNOMIN;
  fit.coefficients.UNLOADED_RADIUS = data.UNLOADED_RADIUS;

  std::vector<TyreTestPoint> points;
  points.reserve(data.points.size());
  for (const RigPoint& p : data.points) points.push_back({p.FZ, p.KAPPA, p.ALPHA, p.GAMMA, p.FX, p.FY, p.MZ});
  for (FitGroup group : {FitGroup::pure_longitudinal, FitGroup::pure_lateral, FitGroup::aligning}) {
    fit.groups.push_back(fit_coefficient_group(group, points, fit.coefficients));
    fit.errors.push_back(fit.groups.back().error);
    const auto& missing = fit.groups.back().not_determined;
    fit.not_determined.insert(fit.not_determined.end(), missing.begin(), missing.end());
  }
  fit.errors.push_back(fit_overturning_moment(data.points, fit.coefficients, fit.not_determined));

  std::vector<LoadDeflectionPoint> load_deflection = data.load_deflection;
  if (load_deflection.empty())
    for (const RigLoadRadii& r : data.radii)
      load_deflection.push_back({data.UNLOADED_RADIUS - r.loaded_radius, r.FZ});
  fit.errors.push_back(fit_load_deflection(load_deflection, fit.coefficients, fit.not_determined));

  std::vector<RollingRadiusPoint> radii;
  for (const RigLoadRadii& r : data.radii) radii.push_back({r.FZ, r.effective_radius});
  fit.errors.push_back(fit_effective_rolling_radius(radii, fit.coefficients, fit.not_determined));
  for (const ChannelFitError& e : fit_relaxation_lengths(data.relaxation, fit.coefficients, fit.not_determined))
    fit.errors.push_back(e);

  const CombinedSlipFit combined = fit_combined_slip(points, fit.coefficients);
  fit.errors.insert(fit.errors.end(), combined.errors.begin(), combined.errors.end());
  fit.not_determined.insert(fit.not_determined.end(), combined.not_determined.begin(), combined.not_determined.end());
  fit.combined_slip_points = !combined.errors.empty();
  for (const NeverDetermined& k : never_determined_by_the_rig()) {
    fit.coefficients.*(find_coefficient(k.key)->member) = find_coefficient(k.key)->neutral;
    fit.not_determined.emplace_back(k.key);
  }

  fit.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return fit;
}

}  // namespace tirefem
