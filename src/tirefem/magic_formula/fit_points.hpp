#pragma once
// The points a coefficient group is fitted to, and what they contain (loads, camber sweeps, slip signs).
// Internal to the fits (fitter.cpp, fit_start_values.cpp, vertical_fit.cpp, relaxation_fit.cpp).
#include <span>
#include <utility>
#include <vector>

#include "tirefem/magic_formula/fitter.hpp"

namespace tirefem::magic_formula_fit {

struct GroupPoints {
  std::vector<TyreTestPoint> points;
  std::vector<double> loads;        // load levels (load_levels), ascending
  int camber_sweeps = 0;            // distinct inclinations with a slip sweep of both signs (0 counts)
  int camber_point_levels = 0;      // load levels with cambered points (a free-rolling one suffices)
  bool camber_both_signs = false;   // sweeps at a positive and at a negative inclination
  bool both_signs = false;          // slips of both signs
  double peak = 0;                  // max |measured|
};

// The group's channel (Fx, Fy or Mz) and slip (kappa or alpha) of a point.
double measured(FitGroup group, const TyreTestPoint& p);
double slip(FitGroup group, const TyreTestPoint& p);
// The pure-slip model value of the group's channel.
double model(FitGroup group, const MagicFormulaCoefficients& c, const TyreTestPoint& p);

// The other slip of a pure-slip point: |kappa| (or |alpha| in rad) within this. A free-rolling point at a
// camber has a small kappa of its own (the rig's at 2°: 8.9e-5, its Fx 0.009 N): it is a lateral point.
constexpr double kPureSlipTolerance = 1e-3;

// Pure-slip points of the group: longitudinal alpha = 0 and gamma = 0; lateral and aligning kappa = 0, and
// gamma = 0 unless `with_camber` (zero within kPureSlipTolerance).
GroupPoints select_points(FitGroup group, std::span<const TyreTestPoint> points, bool with_camber);

// Distinct values: neighbours in sorted order further apart than `tolerance`.
std::vector<double> distinct_values(std::vector<double> values, double tolerance);
// The load levels of a test: a rig holds each load only to its tolerance (tirefem's Qz to about 0.1–0.2%,
// a flat-track machine to a few per cent), so loads whose sorted neighbours lie within kLoadLevelGap of the
// largest load form one level, reported as their mean (ascending). Load-dependence coefficients need
// levels, not the scatter within one: counted as distinct values to 1e-3 of the load, one 5550 N series
// held to ±6 N made three "loads" and its fit of PKX2, PEX2, PEX3 went astray (PEX1 −7e92).
constexpr double kLoadLevelGap = 0.05;
std::vector<double> load_levels(std::vector<double> loads);
// The index in `levels` (load_levels) of the level nearest Fz.
std::size_t nearest_level(double Fz, const std::vector<double>& levels);
// Least-squares line y = a + b x, returned as {a, b} (b = 0 with a single distinct x).
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y);

// A positive coefficient kept within [lo, hi] smoothly for Levenberg-Marquardt, which then varies v ∈ ℝ:
// value(v) = exp(log lo + ½ (log hi − log lo)(1 + tanh v)); parameter() is its inverse, kept off the
// saturated ends (|tanh v| ≤ 0.99). result() is the value a fit reports: a fit that ran into a bound
// ends a little inside it (99.99999999999827 for 100) or, exp(log hi) by round-off, a few ulps beyond
// (100.00000000000004); within 1e-9 of a bound it is set on it, so the coefficient says where it ended.
struct LogBounded {
  double lo = 0, hi = 0;
  double value(double v) const;
  double result(double v) const;
  double parameter(double x) const;
};

}  // namespace tirefem::magic_formula_fit
