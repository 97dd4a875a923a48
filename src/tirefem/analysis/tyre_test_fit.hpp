#pragma once
// The Magic Formula of the virtual rig (issue 12): the PAC2002 coefficients that the rig's table
// determines, fitted by magic_formula/rig_fit.hpp, as a `.tir` property file with the tyre's dimensions,
// the ranges of the test, and a note on every coefficient the rig does not determine.
#include <string>
#include <vector>

#include "tirefem/analysis/tyre_test.hpp"
#include "tirefem/magic_formula/coefficients.hpp"
#include "tirefem/magic_formula/rig_fit.hpp"

namespace tirefem {

struct TyreTestFit {
  TirFile tir;
  std::vector<ChannelFitError> errors;      // Fx, Fy, Mz, Mx, Fz (load–deflection), Re
  std::vector<std::string> not_determined;  // keys written with their neutral values
  double seconds = 0;
};

// The rig's data in the fit's form: its rows, the radii of free rolling per load, and the load–deflection
// curve (deflection from the undeformed tyre, points with Qz > 0).
RigData tyre_test_rig_data(const TyreTestResult& result);

// Fits and fills the property file. `tyre` gives the dimensions (from the carcass line: WIDTH twice its
// largest x, RIM_RADIUS and RIM_WIDTH from the bead point, ASPECT_RATIO the section height over WIDTH),
// `source` names the case for the header. Throws std::invalid_argument when the table cannot be fitted
// (too few points in a group).
TyreTestFit fit_tyre_test(const TyreTestResult& result, const TyreDescription& tyre, const std::string& source);

}  // namespace tirefem
