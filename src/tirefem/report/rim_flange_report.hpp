#pragma once
// Summary entries and table figures of the rim flanges' loads (forms/rim_flange_form.hpp): the push of the
// lower sidewall on each flange, the flange's share of the wheel load, its peak contact pressure and the
// share of the circumference in contact. Pure functions: nothing is solved or written here.
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "tirefem/analysis/rolling.hpp"
#include "tirefem/forms/rim_flange_form.hpp"

namespace tirefem {

toml::table rim_flange_table(const std::string& side, const RimFlangeLoad& load);

// A rolling state's flanges (RollingFigures::rim_flanges) as `rim_flanges`, an array of tables; nothing
// when the tyre has no flange.
void insert_rim_flanges(toml::table& t, const RollingFigures& f);

// The two figures of a state's flanges that its tables carry: the largest axial force and the smallest
// contact fraction (NaN without flanges).
double largest_flange_axial_force_N(const RollingFigures& f);
double smallest_flange_contact_fraction(const RollingFigures& f);

}  // namespace tirefem
