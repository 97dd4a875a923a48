#pragma once
// [mesh] (and a rolling study's own mesh = { ... }) and its checks, including whether the machine can hold
// the linear systems of the mesh (mesh_size_estimate.hpp).
#include <cstddef>
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

// Keys missing in the table keep their value in `m` (the defaults, or the case's mesh for a study's own).
MeshSettings read_mesh(TomlFields& f, const toml::node& n, const std::string& path, MeshSettings m);

// `zones`: each zone needs at least one meridional element.
void check_mesh(const FieldChecker& c, const MeshSettings& m, const std::string& path, std::size_t zones);

}  // namespace tirefem::case_reading
