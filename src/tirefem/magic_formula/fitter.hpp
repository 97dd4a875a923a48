#pragma once
// Nonlinear least-squares fit of PAC2002 coefficient groups to steady-state rig points (Fz, kappa, alpha,
// gamma, Fx, Fy, Mz), W-axis system, SI units.
//
// Library: Eigen's Levenberg-Marquardt (unsupported/Eigen/NonLinearOptimization) with a central-difference
// Jacobian (NumericalDiff, step eps^(1/3)|u|): already a dependency through libeigen3-dev, and a group has
// at most ~25 unknowns and a few hundred residuals, where Ceres' sparse machinery, automatic derivatives
// and robust losses buy nothing. For noise-free data the residual is zero at the solution, so the
// Jacobian's ~1e-11 error does not move it.
//
// Groups, fitted in this order (the aligning moment needs the fitted lateral force):
// - pure longitudinal (points with alpha = 0 and gamma = 0): PCX1, PDX1-2, PEX1-4, PKX1-3, PHX1-2, PVX1-2
//   on Fx (PDX3 never: no cambered kappa sweeps are used);
// - pure lateral (points with kappa = 0): PCY1, PDY1-3, PEY1-4, PKY1-3, PHY1-3, PVY1-4 on Fy;
// - aligning (points with kappa = 0): QBZ1-5, QBZ9, QCZ1, QDZ1-4, QDZ6-9, QEZ1-5, QHZ1-4 on Mz.
// A coefficient is fitted only when the data determine it: load variations need 2 (linear) or 3
// (quadratic, exponential) distinct loads; camber terms slip sweeps (>= 2 slips of each sign) at 2 distinct
// inclinations (gamma = 0 counts), QDZ4 (gamma^2 beside QDZ3 gamma) at 3, QBZ5 (|gamma| beside QBZ4 gamma)
// at a positive and a negative one; the camber shifts PVY3 (camber thrust) and QDZ8 (the residual moment's
// camber term), with cambered points at 2 load levels PVY4 and QDZ9, need cambered points only, free-rolling
// ones suffice (PHY3 and QHZ3, which such points cannot tell from them, then stay neutral). The
// sign-dependent terms (PEX4, PEY3, PEY4, QEZ4, QEZ5) and the shifts (PHX1-2, PVX1-2, PHY1-2, PVY1-2,
// QHZ1-2: from one side they trade against each other) need slips of both signs. QBZ10 is never fitted: it
// multiplies By Cy, nearly proportional to QBZ9 over a rig's loads. A coefficient not fitted is set to
// its neutral value and listed in `not_determined`.
// Parametrisation: the curvature factors E (4.E14, 4.E24) are fitted as E+ = E1(1 - E4), E- = E1(1 + E4),
// E2/E1, E3/E1 and E1 E5 and converted back (fitter.cpp): the products of coefficients are badly scaled
// (PEY1 = 0.004, PEY3 = 41.5 in a public file) and made the plain fit stall. Bounds by transformation:
// C > 0, D > 0 (PCX1, PDX1, PCY1, PDY1, QCZ1 = exp(u)), PKY2 > 0, E+-, QEZ1 <= 1 (1 - exp(u)); the
// evaluator limits E <= 1 at other loads.
// Start values from the data (fit_start_values.cpp): per load, least-squares lines through the 5 slips
// nearest zero give the slip stiffness (PKX1-2; PKY2 from the ratio at two loads, then PKY1), the shift
// (PHX, PHY) and the trail -dMz/dFy and residual moment (QDZ1-2, QDZ6-7); the peak |F| gives mu (PDX1-2,
// PDY1-2), the fall after the peak C. Passes: the nominal-load coefficients, then all without camber on the
// gamma = 0 points, then (with cambered sweeps) all on all points. The passes run from three starts (the
// shape factor C from the data, 0.7 and 1.4 times it) and the fit with the least sum of squares and C <= 2
// is kept: a curve without a peak has more than one minimum (fitter.cpp, kShapeFactorStarts).
#include <span>
#include <string>
#include <vector>

#include "tirefem/magic_formula/coefficients.hpp"

namespace tirefem {

struct TyreTestPoint {
  double Fz = 0, kappa = 0, alpha = 0, gamma = 0;  // N, -, rad, rad
  double Fx = 0, Fy = 0, Mz = 0;                   // N, N, N m
};

enum class FitGroup { pure_longitudinal, pure_lateral, aligning };

struct ChannelFitError {
  std::string channel;      // "Fx", "Fy" or "Mz"
  int points = 0;
  double rms = 0;           // N or N m
  double peak = 0;          // max |data| of the channel's points
  double relative_rms = 0;  // rms / peak
};

struct GroupFitResult {
  FitGroup group = FitGroup::pure_longitudinal;
  std::vector<std::string> fitted;
  std::vector<std::string> not_determined;
  ChannelFitError error;
  int function_evaluations = 0;
  bool converged = false;
  double seconds = 0;
};

struct MagicFormulaFit {
  MagicFormulaCoefficients coefficients;
  std::vector<GroupFitResult> groups;
};

// Fits one group in place: `coefficients` must hold FNOMIN, UNLOADED_RADIUS and the scaling factors (and,
// for the aligning group, the fitted lateral coefficients). Throws std::invalid_argument when the group has
// fewer usable points than unknowns.
GroupFitResult fit_coefficient_group(FitGroup group, std::span<const TyreTestPoint> points,
                                     MagicFormulaCoefficients& coefficients);

// All three groups in order; `start` supplies FNOMIN, UNLOADED_RADIUS, scalings and every coefficient the
// fit does not touch.
MagicFormulaFit fit_magic_formula(std::span<const TyreTestPoint> points, const MagicFormulaCoefficients& start);

}  // namespace tirefem
