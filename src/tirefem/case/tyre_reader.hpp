#pragma once
// [tyre]: name, cord_rubber_rule, profile, plies, zones, interlayer and tread (each read and checked by its
// own reader: profile_reader, zone_reader, tread_reader).
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

struct TyreRead {
  TyreDescription tyre;
  bool shear_modulus_given = false;  // tyre.tread.shear_modulus (required only by rolling studies)
};

TyreRead read_tyre(TomlFields& f, const toml::node& n, const std::string& path);

// All value checks of the tyre (paths from "tyre"); `rolls`: a rolling study needs the tread shear
// modulus. Returns the profile's arc length.
double check_tyre(const FieldChecker& c, const TyreDescription& t, bool rolls);

// Outer radius of the tread surface on the equator, r(0) + h(0) + hp(0) (mm): the wheel axis height of
// the undeformed tyre on the road (TyreMesh::axis_z), the scale of drums and rolling radii. The tyre must
// have been checked.
double tyre_outer_radius(const TyreDescription& t);

}  // namespace tirefem::case_reading
