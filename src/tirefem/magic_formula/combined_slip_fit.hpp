#pragma once
// Fit of the PAC2002 combined-slip weighting functions to points where kappa and alpha are both non-zero
// (gamma = 0), the pure-slip coefficients held as fitted:
// - Fx = Gxa Fx0 (4.E50-4.E57): RBX1 in [1, 50], RBX2, RCX1 in [0.5, 1.2];
// - Fy = Gyk Fy0 + SVyk (4.E58-4.E67): RBY1 in [1, 50], RBY2, RCY1 in [0.5, 1.2].
// The shifts and curvatures (RHX1, REX1-2, RBY3, RHY1-2, REY1-2) and the kappa-induced side force
// RVY1-6 stay neutral: a tyre that is its own mirror image has no shift, and a rig grid of a few slips
// does not separate curvature from slope. Eigen's Levenberg-Marquardt with a central-difference Jacobian
// (as the pure-slip groups, fitter.hpp), from three starts of the slope factor; the best fit is kept.
// Each weighting G = cos(C atan(B s)) is in the other slip s: B1 and C need two levels of |s| (|alpha| for
// Fx, |kappa| for Fy), the fall B2 two levels of the force's own slip as well (else B2 = 0). What the
// points do not determine is listed as not determined, at its neutral value.
#include <span>
#include <string>
#include <vector>

#include "tirefem/magic_formula/fitter.hpp"

namespace tirefem {

// The combined-slip keys of PAC2002 (those fitted and those held neutral).
std::span<const char* const> combined_slip_keys();

struct CombinedSlipFit {
  std::vector<std::string> fitted, not_determined;  // keys
  std::vector<ChannelFitError> errors;               // "Fx combined", "Fy combined" (none without points)
};

// Fits into `c`, whose pure-slip coefficients must already be fitted.
CombinedSlipFit fit_combined_slip(std::span<const TyreTestPoint> points, MagicFormulaCoefficients& c);

}  // namespace tirefem
