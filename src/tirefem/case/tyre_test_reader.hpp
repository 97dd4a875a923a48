#pragma once
// [[tyre_test]] studies: a virtual flat-track rig (issue 12), the data of a Magic Formula fit.
//   name                 as for [[load_curve]]
//   nominal_load         FNOMIN, N (default 3700)
//   loads                the test loads as multiples of nominal_load (default [0.5, 1, 1.5])
//   load_tolerance       as for [[footprint]] (default 1e-3): every point is held at its load
//   friction             Coulomb coefficient μ (default 0.7)
//   slip_sweep           { from = -0.15, to = 0.15, points = 15, spacing = "quadratic" }: longitudinal slips
//                        κ, Qz held; spacing "quadratic" (denser near 0, the default) or "even"
//   angle_sweep          { from = -12, to = 12, points = 15, spacing = "quadratic" }: slip angles, degrees,
//                        Qz held, κ = 0
//   cambers              [γ, ...] degrees: a free-rolling state at each, at every load (default none)
//   vertical             { max_deflection = 40, points = 10 }: the load–deflection curve (half model)
//   mesh                 optional own mesh, keys of [mesh]; it must be the full model
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/case/study_reader.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

TyreTestStudy read_tyre_test(TomlFields& f, const toml::node& n, const std::string& path, const MeshSettings& case_mesh);

// All checks but the name (check_study_name) and the own mesh (check_mesh).
void check_tyre_test(const FieldChecker& c, const TyreTestStudy& s, const std::string& path, const TyreScale& tyre,
                     bool case_half_model);

}  // namespace tirefem::case_reading
