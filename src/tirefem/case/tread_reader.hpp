#pragma once
// [tyre.interlayer] thickness h(s) and [tyre.tread] (height hp(s), end_s, stiffness kp, shear_modulus),
// and their checks. Quantities along the meridian are a number or a table { s = [...], value = [...] }.
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

// Reads both tables into `d`. Returns whether tread.shear_modulus was given (only rolling needs it).
bool read_interlayer_and_tread(TomlFields& f, const toml::table& tyre, const std::string& tyre_path,
                               TyreDescription& d);

void check_table(const FieldChecker& c, const Table& t, const std::string& path, const Bound& bound);
// Where the carcass line bends concavely (curvature κ < 0, see MeridianProfile::curvature), the outer face,
// h(s) off it along the normal, folds over unless h < 1/|κ|. The profile must have been checked.
void check_interlayer_fold(const FieldChecker& c, const TyreDescription& t, const std::string& path);
// `length`: the profile's arc length. The shear modulus is checked when `rolls` (a rolling study uses
// it) or when it was given (not zero).
void check_interlayer_and_tread(const FieldChecker& c, const TyreDescription& t, double length, bool rolls);

}  // namespace tirefem::case_reading
