#include "tirefem/magic_formula/relaxation_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "tirefem/magic_formula/evaluator.hpp"
#include "tirefem/magic_formula/fit_points.hpp"

namespace tirefem {
namespace {

// The nonlinear parameters stay within the grids' ranges, smoothly (as BREFF in vertical_fit.cpp): PTX3 in
// [−5, 5] (beyond, exp(−PTX3 dfz) over a rig's loads is a step no tyre has) and PTY2 in [0.2, 20] FNOMIN
// (with two or three loads and sigma_alpha nearly linear in Fz an unbounded PTY2 ran off to 800, the sine's
// linear part, which the bound keeps to within 0.1% there).
constexpr double kMaxExponent = 5.0, kMinPeak = 0.2, kMaxPeak = 20.0;
constexpr magic_formula_fit::LogBounded kPeak{kMinPeak, kMaxPeak};
double exponent_of(double v) { return kMaxExponent * std::tanh(v); }
double v_of_exponent(double p) { return std::atanh(std::clamp(p / kMaxExponent, -0.99, 0.99)); }

// y_i = (a + b x_i) exp(-PTX3(v) x_i) (longitudinal: x = dfz) or y_i = a sin(2 atan(x_i / PTY2(v))) (lateral:
// x = Fz/Fz0), u = (a, b, v) or (a, v).
struct LengthResidual {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  const std::vector<double>* x;
  const std::vector<double>* y;
  bool lateral = false;
  int inputs() const { return lateral ? 2 : 3; }
  int values() const { return static_cast<int>(x->size()); }
  static double model(const Eigen::VectorXd& u, double x, bool lateral) {
    return lateral ? u[0] * std::sin(2 * std::atan(x / kPeak.value(u[1]))) : (u[0] + u[1] * x) * std::exp(-exponent_of(u[2]) * x);
  }
  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& r) const {
    for (std::size_t i = 0; i < x->size(); ++i) r[static_cast<Eigen::Index>(i)] = model(u, (*x)[i], lateral) - (*y)[i];
    return 0;
  }
};

void minimise(const LengthResidual& f, Eigen::VectorXd& u) {
  Eigen::NumericalDiff<LengthResidual, Eigen::Central> numerical(f, 3.7e-11);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<LengthResidual, Eigen::Central>> lm(numerical);
  lm.parameters.ftol = lm.parameters.xtol = 1e-15;
  lm.parameters.maxfev = 2000;
  lm.minimize(u);
}

// Least squares of y ≈ Σ_k c_k basis_k(x) over the points: the coefficients and the residual's square.
Eigen::VectorXd linear_fit(const std::vector<double>& x, const std::vector<double>& y, int columns,
                           const auto& basis, double& squared_residual) {
  Eigen::MatrixXd A(static_cast<Eigen::Index>(x.size()), columns);
  Eigen::VectorXd b(static_cast<Eigen::Index>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int k = 0; k < columns; ++k) A(static_cast<Eigen::Index>(i), k) = basis(k, x[i]);
    b[static_cast<Eigen::Index>(i)] = y[i];
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
  squared_residual = (A * c - b).squaredNorm();
  return c;
}

ChannelFitError length_error(const char* channel, const std::vector<double>& fitted, const std::vector<double>& data) {
  ChannelFitError e;
  e.channel = channel;
  e.points = static_cast<int>(data.size());
  double sum = 0;
  for (std::size_t i = 0; i < data.size(); ++i) {
    sum += (fitted[i] - data[i]) * (fitted[i] - data[i]);
    e.peak = std::max(e.peak, std::abs(data[i]));
  }
  e.rms = data.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(data.size()));
  e.relative_rms = e.peak > 0 ? e.rms / e.peak : 0.0;
  return e;
}

}  // namespace

std::vector<ChannelFitError> fit_relaxation_lengths(std::span<const RelaxationPoint> points, MagicFormulaCoefficients& c,
                                                    std::vector<std::string>& not_determined) {
  const double Fz0 = c.FNOMIN * c.LFZO, R0 = c.UNLOADED_RADIUS;
  std::vector<ChannelFitError> errors;
  c.PTX1 = c.PTX2 = c.PTX3 = 0;
  c.PTY1 = c.PTY2 = 0;
  std::vector<double> dfz, yk, rho, ya, loads_k, loads_a;
  for (const RelaxationPoint& p : points) {
    if (p.sigma_kappa) {
      dfz.push_back((p.Fz - Fz0) / Fz0);
      yk.push_back(*p.sigma_kappa * Fz0 / (p.Fz * R0));
      loads_k.push_back(p.Fz);
    }
    if (p.sigma_alpha) {
      rho.push_back(p.Fz / Fz0);
      ya.push_back(*p.sigma_alpha / R0);
      loads_a.push_back(p.Fz);
    }
  }
  const auto evaluate = [&](const std::vector<double>& loads, bool lateral) {
    std::vector<double> v;
    for (double Fz : loads) {
      const RelaxationLengths r = relaxation_lengths(c, Fz);
      v.push_back(lateral ? r.sigma_alpha : r.sigma_kappa);
    }
    return v;
  };

  // Longitudinal.
  const std::size_t nk = magic_formula_fit::load_levels(loads_k).size();
  if (nk == 0) not_determined.insert(not_determined.end(), {"PTX1", "PTX2", "PTX3"});
  if (nk >= 1) {
    const auto basis = [&](double p) { return [p](int k, double x) { return (k == 0 ? 1.0 : x) * std::exp(-p * x); }; };
    double residual = 0;
    if (nk < 3) {
      not_determined.emplace_back("PTX3");
      if (nk == 1) not_determined.emplace_back("PTX2");
      const Eigen::VectorXd ab = linear_fit(dfz, yk, static_cast<int>(nk), basis(0.0), residual);
      c.PTX1 = ab[0];
      c.PTX2 = nk == 2 ? ab[1] : 0.0;
    } else {
      double best_p = 0, best = INFINITY;
      for (int i = 0; i <= 100; ++i) {
        const double p = kMaxExponent * (-1.0 + 0.02 * i);
        linear_fit(dfz, yk, 2, basis(p), residual);
        if (residual < best) best = residual, best_p = p;
      }
      const Eigen::VectorXd ab = linear_fit(dfz, yk, 2, basis(best_p), residual);
      Eigen::VectorXd u(3);
      u << ab[0], ab[1], v_of_exponent(best_p);
      minimise(LengthResidual{&dfz, &yk, false}, u);
      c.PTX1 = u[0], c.PTX2 = u[1], c.PTX3 = exponent_of(u[2]);
    }
    std::vector<double> data;
    for (const RelaxationPoint& p : points)
      if (p.sigma_kappa) data.push_back(*p.sigma_kappa);
    errors.push_back(length_error("sigma_kappa", evaluate(loads_k, false), data));
  }

  // Lateral.
  const std::size_t na = magic_formula_fit::load_levels(loads_a).size();
  if (na == 0) not_determined.insert(not_determined.end(), {"PTY1", "PTY2"});
  if (na >= 1) {
    const auto basis = [](double peak_load) {
      return [peak_load](int, double x) { return std::sin(2 * std::atan(x / peak_load)); };
    };
    double residual = 0;
    if (na == 1) {
      not_determined.emplace_back("PTY2");
      c.PTY2 = c.PKY2 > 0 ? c.PKY2 : 1.0;
      c.PTY1 = linear_fit(rho, ya, 1, basis(c.PTY2), residual)[0];
    } else {
      double best_peak = 1, best = INFINITY;
      for (int i = 0; i <= 100; ++i) {
        const double peak = kMinPeak * std::pow(kMaxPeak / kMinPeak, i / 100.0);
        linear_fit(rho, ya, 1, basis(peak), residual);
        if (residual < best) best = residual, best_peak = peak;
      }
      Eigen::VectorXd u(2);
      u << linear_fit(rho, ya, 1, basis(best_peak), residual)[0], kPeak.parameter(best_peak);
      minimise(LengthResidual{&rho, &ya, true}, u);
      c.PTY1 = u[0], c.PTY2 = kPeak.result(u[1]);
    }
    std::vector<double> data;
    for (const RelaxationPoint& p : points)
      if (p.sigma_alpha) data.push_back(*p.sigma_alpha);
    errors.push_back(length_error("sigma_alpha", evaluate(loads_a, true), data));
  }
  return errors;
}

}  // namespace tirefem
