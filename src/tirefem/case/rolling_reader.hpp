#pragma once
// [[rolling]] studies: steady rolling at the deflection of a static footprint at target_load.
//   name, support              as for [[footprint]]; a surface support must not depend on y
//   target_load                N (default 3700); load_tolerance as for [[footprint]] (default 1e-3)
//   friction                   Coulomb coefficient μ between tread and support, in (0, 5] (default 0.7)
//   reverse                    true: the wheel travels in −y (default false)
//   mesh                       optional own mesh, keys of [mesh] (missing ones are the case's)
//   states                     [{ state = ..., name = ... }, ...], the state's keys by kind:
//                                "free"                                   (Qy = 0)
//                                "given_slip",   slip = κ (required)      κ in (−1, 10]
//                                "given_radius", rolling_radius = mm (required), implying κ = R/Rk − 1 in
//                                                [−0.99, 10] with R the tyre's outer radius
//                                "full_stick",   slip = κ (default 0)
//                                "full_slip",    wheel = "spinning" (default) or "locked"
//                              name: [A-Za-z0-9_.+-], not starting with '.', unique in the study; default
//                              "free", "slip_0.05", "radius_280", "full_stick", "full_slip_spinning" /
//                              "full_slip_locked"
//   sweep                      { from = -0.1, to = 0.1, points = 15, hold = "deflection" | "load" }:
//                              Qy(κ) at `points` (2..200) slips evenly in [from, to], −1 < from < to ≤ 10
// At least one state or a sweep.
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/case/study_reader.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

RollingStudy read_rolling(TomlFields& f, const toml::node& n, const std::string& path, const MeshSettings& case_mesh);

// A slip κ: finite, > −1, ≤ kMaxSlip. An angle in degrees: finite, |angle| ≤ largest.
void check_slip(const FieldChecker& c, double v, const std::string& path);
void check_angle(const FieldChecker& c, double degrees, const std::string& path, double largest);

// All checks but the name (check_study_name) and the own mesh (check_mesh).
// `case_half_model`: the case's mesh, which a study without its own mesh rolls on.
void check_rolling(const FieldChecker& c, const RollingStudy& s, const std::string& path, const TyreScale& tyre,
                   bool case_half_model);

}  // namespace tirefem::case_reading
