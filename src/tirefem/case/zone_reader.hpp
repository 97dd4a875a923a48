#pragma once
// [tyre.plies.NAME] and [[tyre.zones]] with their inner and outer faces (plies, rubber layers, a direct
// stiffness), and their checks: ply values, face stiffness, zone ends reaching the bead, core moduli.
#include <map>
#include <string>
#include <vector>

#include "tirefem/case/case.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

CordRubberRule read_rule(TomlFields& f, const toml::node& n, const std::string& path);
// The named plies of [tyre.plies] (each checked as it is read).
std::map<std::string, Ply> read_plies(TomlFields& f, const toml::table& tyre, const std::string& tyre_path);
std::vector<Zone> read_zones(TomlFields& f, const toml::table& tyre, const std::string& tyre_path,
                             const std::map<std::string, Ply>& plies, CordRubberRule default_rule);

void check_ply(const FieldChecker& c, const Ply& p, const std::string& path);
void check_face_stiffness(const FieldChecker& c, const Eigen::Matrix3d& a, const std::string& path);
void check_face(const FieldChecker& c, const FaceLayup& f, const std::string& path);
// The zones (path "tyre.zones"): increasing ends, the last one at the bead (`length`, the profile's arc
// length, within kZoneEndTolerance), faces and core moduli.
void check_zones(const FieldChecker& c, const std::vector<Zone>& zones, double length, const std::string& path);

}  // namespace tirefem::case_reading
