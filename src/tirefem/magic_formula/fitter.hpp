#pragma once
// Nonlinear least-squares fit of PAC2002 coefficient groups to steady-state rig points (Fz, kappa, alpha,
// gamma, Fx, Fy, Mz), W-axis system, SI units.
//
// Library: Eigen's Levenberg-Marquardt (unsupported/Eigen/NonLinearOptimization) with a central-difference
// Jacobian (NumericalDiff): already a dependency through libeigen3-dev, and a group has at most ~20
// unknowns and a few hundred residuals, where Ceres' sparse machinery, automatic derivatives and robust
// losses buy nothing.
//
// Groups, fitted in this order (the aligning moment needs the fitted lateral force):
// - pure longitudinal (points with alpha = 0): PCX1, PDX1-3, PEX1-4, PKX1-3, PHX1-2, PVX1-2 on Fx;
// - pure lateral (points with kappa = 0): PCY1, PDY1-3, PEY1-4, PKY1-3, PHY1-3, PVY1-4 on Fy;
// - aligning (points with kappa = 0): QBZ1-5, QBZ9, QCZ1, QDZ1-4, QDZ6-9, QEZ1-5, QHZ1-4 on Mz.
// A coefficient is fitted only when the data determine it: load variations need 2 (linear) or 3
// (quadratic, exponential) distinct loads, camber terms 2 (or 3 for |gamma| and gamma^2 terms) distinct
// inclination angles, the sign-dependent curvature terms (PEX4, PEY3, QEZ4) slips of both signs. QBZ10 is
// never fitted: it multiplies By Cy, nearly proportional to QBZ9 over a rig's loads. A coefficient not
// fitted is set to its neutral value and listed in `not_determined`.
// Bounds by parameter transformation: C > 0 and D > 0 (PCX1, PDX1, PCY1, PDY1, QCZ1 = exp(u)), E <= 1 at
// the nominal load (PEX1, PEY1, QEZ1 = 1 - exp(u)); the evaluator limits E <= 1 at other loads.
// Start values from the data: per load the peak |F| gives mu (PDX1, PDX2), the slope through the two
// smallest slips gives Kxk/Fz and Kya (PKX1, PKX2, PKY1), the trail -Mz/Fy at the smallest slip angle gives
// QDZ1; shape and curvature factors start at typical values. A first pass fits only the nominal-load
// coefficients (C, D, E, K), a second all determined ones.
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
