#include "tirefem/magic_formula/vertical_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "tirefem/magic_formula/evaluator.hpp"
#include "tirefem/magic_formula/fit_points.hpp"

namespace tirefem {
namespace {

ChannelFitError channel_error(const char* channel, const std::vector<double>& residual, const std::vector<double>& data) {
  ChannelFitError e;
  e.channel = channel;
  e.points = static_cast<int>(data.size());
  double sum = 0;
  for (double r : residual) sum += r * r;
  e.rms = std::sqrt(sum / static_cast<double>(residual.size()));
  for (double d : data) e.peak = std::max(e.peak, std::abs(d));
  e.relative_rms = e.peak > 0 ? e.rms / e.peak : 0.0;
  return e;
}

// BREFF is kept within [kMinBreff, kMaxBreff]. Beyond 100, atan(BREFF rho) is within 2% of π/2 at any rig
// load above half the nominal one, so the data cannot tell it from a constant. With three loads the
// unbounded fit then ran BREFF off to 1e10–1e12 (the example's quick rig), which is a step in Re at
// Fz = 0 that no tyre has. Published passenger-tyre files have 7–10.
constexpr magic_formula_fit::LogBounded kBreff{kMinBreff, kMaxBreff};

// (R0 - Re) Cz/FNOMIN = DREFF atan(BREFF rho) + FREFF rho, rho = Fz/FNOMIN.
struct RadiusResidual {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  const std::vector<double>* rho;
  const std::vector<double>* y;
  int inputs() const { return 3; }
  int values() const { return static_cast<int>(rho->size()); }
  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& r) const {  // u = (v of BREFF, DREFF, FREFF)
    for (std::size_t i = 0; i < rho->size(); ++i)
      r[static_cast<Eigen::Index>(i)] = u[1] * std::atan(kBreff.value(u[0]) * (*rho)[i]) + u[2] * (*rho)[i] - (*y)[i];
    return 0;
  }
};

}  // namespace

ChannelFitError fit_load_deflection(std::span<const LoadDeflectionPoint> points, MagicFormulaCoefficients& c,
                                    std::vector<std::string>& not_determined) {
  const double R0 = c.UNLOADED_RADIUS, Fz0 = c.FNOMIN;
  std::vector<double> deflections;
  for (const auto& p : points) deflections.push_back(p.deflection);
  const auto distinct = magic_formula_fit::distinct_values(deflections, 1e-9);
  if (distinct.empty() || (distinct.size() == 1 && distinct[0] == 0))
    throw std::invalid_argument("Magic Formula vertical fit: no load-deflection points");
  const bool quadratic = distinct.size() >= 3;
  // Fz/FNOMIN = Q_FZ1 x + Q_FZ2 x^2, x = rho/R0: linear least squares (QR).
  Eigen::MatrixXd A(static_cast<Eigen::Index>(points.size()), quadratic ? 2 : 1);
  Eigen::VectorXd b(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].deflection / R0;
    const auto row = static_cast<Eigen::Index>(i);
    A(row, 0) = x;
    if (quadratic) A(row, 1) = x * x;
    b[row] = points[i].Fz / Fz0;
  }
  const Eigen::VectorXd q = A.colPivHouseholderQr().solve(b);
  c.Q_FZ1 = q[0];
  c.Q_FZ2 = quadratic ? q[1] : 0.0;
  if (!quadratic) not_determined.emplace_back("Q_FZ2");
  c.VERTICAL_STIFFNESS = Fz0 / R0 * std::sqrt(c.Q_FZ1 * c.Q_FZ1 + 4 * c.Q_FZ2);
  std::vector<double> residual, data;
  for (const auto& p : points) {
    const double x = p.deflection / R0;
    residual.push_back(Fz0 * (c.Q_FZ1 * x + c.Q_FZ2 * x * x) - p.Fz);
    data.push_back(p.Fz);
  }
  return channel_error("Fz", residual, data);
}

ChannelFitError fit_effective_rolling_radius(std::span<const RollingRadiusPoint> points, MagicFormulaCoefficients& c,
                                             std::vector<std::string>& not_determined) {
  if (c.VERTICAL_STIFFNESS <= 0) throw std::invalid_argument("Magic Formula rolling radius fit: no VERTICAL_STIFFNESS");
  const double R0 = c.UNLOADED_RADIUS, Fz0 = c.FNOMIN, Cz = c.VERTICAL_STIFFNESS;
  c.Q_RE0 = 1;
  std::vector<double> rho, y, loads;
  for (const auto& p : points) {
    rho.push_back(p.Fz / Fz0);
    y.push_back((R0 - p.effective_radius) * Cz / Fz0);
    loads.push_back(p.Fz);
  }
  const std::size_t distinct = magic_formula_fit::load_levels(loads).size();
  if (distinct == 0) throw std::invalid_argument("Magic Formula rolling radius fit: no points");
  c.BREFF = c.DREFF = c.FREFF = 0;
  if (distinct < 3) {
    not_determined.insert(not_determined.end(), {"BREFF", "DREFF"});
    double sxy = 0, sxx = 0;  // y = FREFF rho
    for (std::size_t i = 0; i < rho.size(); ++i) sxy += rho[i] * y[i], sxx += rho[i] * rho[i];
    c.FREFF = sxy / sxx;
  } else {
    // Variable projection on a grid of BREFF, then all three together.
    auto linear_part = [&](double B, double& residual) {
      Eigen::MatrixXd A(static_cast<Eigen::Index>(rho.size()), 2);
      Eigen::VectorXd b(static_cast<Eigen::Index>(rho.size()));
      for (std::size_t i = 0; i < rho.size(); ++i) {
        A(static_cast<Eigen::Index>(i), 0) = std::atan(B * rho[i]);
        A(static_cast<Eigen::Index>(i), 1) = rho[i];
        b[static_cast<Eigen::Index>(i)] = y[i];
      }
      const Eigen::Vector2d x = A.colPivHouseholderQr().solve(b);
      residual = (A * x - b).squaredNorm();
      return x;
    };
    double best_B = 1, best = INFINITY;
    for (int i = 0; i <= 90; ++i) {
      const double B = kMinBreff * std::pow(kMaxBreff / kMinBreff, i / 90.0);
      double residual = 0;
      linear_part(B, residual);
      if (residual < best) best = residual, best_B = B;
    }
    double unused = 0;
    const Eigen::Vector2d DF = linear_part(best_B, unused);
    RadiusResidual functor{&rho, &y};
    Eigen::NumericalDiff<RadiusResidual, Eigen::Central> numerical(functor, 3.7e-11);
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<RadiusResidual, Eigen::Central>> lm(numerical);
    lm.parameters.ftol = lm.parameters.xtol = 1e-15;
    lm.parameters.maxfev = 2000;
    Eigen::VectorXd u(3);
    u << kBreff.parameter(best_B), DF[0], DF[1];
    lm.minimize(u);
    c.BREFF = kBreff.result(u[0]);  // on the bound if it ran into one: the file then says so
    c.DREFF = u[1];
    c.FREFF = u[2];
  }
  std::vector<double> residual, data;
  for (const auto& p : points) {
    residual.push_back(effective_rolling_radius(c, p.Fz) - p.effective_radius);
    data.push_back(R0 - p.effective_radius);  // the peak is of the radius' fall from R0
  }
  auto e = channel_error("Re", residual, data);
  return e;
}

}  // namespace tirefem
