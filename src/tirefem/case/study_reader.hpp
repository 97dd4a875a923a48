#pragma once
// [[load_curve]] and [[footprint]] studies, the fields all studies share (name, support, theory), and their
// checks; study names name output files.
#include <map>
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/case/toml_fields.hpp"

namespace tirefem::case_reading {

// What the study checks need to know of the tyre.
struct TyreScale {
  double outer_radius = 0.0;    // tyre_outer_radius: drums, rolling radii
  double section_height = 0.0;  // outer radius − the profile's smallest r: the deepest a support can press
};

LoadCurveStudy read_load_curve(TomlFields& f, const toml::node& n, const std::string& path);
FootprintStudy read_footprint(TomlFields& f, const toml::node& n, const std::string& path);
// name and support of any study, into `name` and `support`.
void read_study_name_and_support(TomlFields& f, const toml::table& t, const std::string& path, std::string& name,
                                 SupportDescription& support);

// A name that becomes a file name: non-empty, at most kMaxNameLength characters, only the characters
// `allowed` describes (`allowed_chars` besides letters and digits), not starting with '.' ("." and ".."
// are folders, a leading '.' hides a file). `what`: what the name names, for the message.
void check_file_name(const FieldChecker& c, const std::string& name, const std::string& path,
                     std::string_view allowed_chars, std::string_view allowed, std::string_view what);
// Study names: [A-Za-z0-9_-], unique among all studies (`seen`: name -> path of the study that has it).
void check_study_name(const FieldChecker& c, const std::string& name, const std::string& path,
                      std::map<std::string, std::string>& seen);
void check_load(const FieldChecker& c, double target_load, double load_tolerance, const std::string& path);
void check_load_curve(const FieldChecker& c, const LoadCurveStudy& s, const std::string& path, const TyreScale& tyre);
void check_footprint(const FieldChecker& c, const FootprintStudy& s, const std::string& path, const TyreScale& tyre);

}  // namespace tirefem::case_reading
