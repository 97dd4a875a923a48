#pragma once
// Start values of a coefficient group's fit, read off the data load by load. Internal to the fitter.
#include "tirefem/magic_formula/fit_points.hpp"

namespace tirefem::magic_formula_fit {

// Sets the group's main coefficients from the gamma = 0 points of `data`; the others keep the values they
// have in `c` (the fitter sets them neutral first). `c` holds FNOMIN, UNLOADED_RADIUS and the scalings, and,
// for the aligning group, the fitted lateral coefficients.
void set_start_values(FitGroup group, const GroupPoints& data, MagicFormulaCoefficients& c);

}  // namespace tirefem::magic_formula_fit
