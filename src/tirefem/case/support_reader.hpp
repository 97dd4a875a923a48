#pragma once
// A study's support = { kind = "plane" } | { kind = "drum", diameter } | { kind = "surface", terms }, and
// its checks.
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

SupportDescription read_support(TomlFields& f, const toml::node& n, const std::string& path);

// `tyre_radius`: the tyre's outer radius (tyre_outer_radius). A drum is a test drum: its radius at least
// the tyre's (a smaller cylinder under the tyre is a different experiment, which the model's contact
// search — the road below the axle — does not cover), its diameter at most kMaxDrumDiameter (100 m; a
// bigger drum is a plane, and the cylinder's curvature is lost in round-off).
void check_support(const FieldChecker& c, const SupportDescription& s, const std::string& path, double tyre_radius);

}  // namespace tirefem::case_reading
