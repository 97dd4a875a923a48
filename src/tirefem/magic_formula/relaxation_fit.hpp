#pragma once
// Fit of the transient coefficients PTX1–PTX3 and PTY1–PTY2 (the relaxation lengths, evaluator.hpp's
// relaxation_lengths) to relaxation lengths measured per load, at zero camber:
//   sigma_kappa Fz0/(Fz R0) = (PTX1 + PTX2 dfz) exp(-PTX3 dfz),   sigma_alpha/R0 = PTY1 sin(2 atan(Fz/(PTY2 Fz0))).
// The rig measures them as sigma = K/C (slip or cornering stiffness over the standing tyre's tangential
// stiffness: analysis/standing_stiffness.hpp). With one load PTX1 alone (PTX2 = PTX3 = 0), with two
// PTX1, PTX2 (PTX3 = 0), with three or more all three: the exponent chosen on a grid (−5..5) with the linear
// pair solved for, then all three by Levenberg-Marquardt (PTX3 kept within ±5). PTY1 and PTY2 need two
// loads: PTY2 on a logarithmic grid (0.2..20) with PTY1 solved for, then both by Levenberg-Marquardt
// (PTY2 kept within the grid's range); with one
// load PTY2 = PKY2 (sigma_alpha then follows Kya's load dependence, a lateral stiffness independent of
// load), not determined. Lengths without data leave their coefficients at 0, not determined.
#include <optional>
#include <span>
#include <vector>

#include "tirefem/magic_formula/fitter.hpp"

namespace tirefem {

struct RelaxationPoint {
  double Fz = 0;                      // N
  std::optional<double> sigma_kappa;  // m
  std::optional<double> sigma_alpha;  // m
};

// Sets PTX1–3 and PTY1–2 (FNOMIN, UNLOADED_RADIUS and PKY2 already in `c`); the errors of the lengths
// with data ("sigma_kappa", "sigma_alpha", m).
std::vector<ChannelFitError> fit_relaxation_lengths(std::span<const RelaxationPoint> points, MagicFormulaCoefficients& c,
                                                    std::vector<std::string>& not_determined);

}  // namespace tirefem
