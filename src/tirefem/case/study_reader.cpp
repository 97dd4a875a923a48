#include "tirefem/case/study_reader.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tirefem/case/support_reader.hpp"

namespace tirefem::case_reading {

void read_study_name_and_support(TomlFields& f, const toml::table& t, const std::string& path, std::string& name,
                                 SupportDescription& support) {
  name = f.string(f.need(t, path, "name", "a string ([A-Za-z0-9_-], unique among all studies)"), join(path, "name"));
  support = read_support(f,
                         f.need(t, path, "support",
                                "a table { kind = \"plane\" }, { kind = \"drum\", diameter = mm } or "
                                "{ kind = \"surface\", terms = [...] }"),
                         join(path, "support"));
}

namespace {

bool read_theory_is_linear(TomlFields& f, const toml::table& t, const std::string& path) {
  if (const toml::node* v = f.get(t, path, "theory"))
    return f.choice(*v, join(path, "theory"), {"nonlinear", "linear"}) == 1;
  return false;
}

DeflectionOrigin read_deflection_from(TomlFields& f, const toml::table& t, const std::string& path) {
  if (const toml::node* v = f.get(t, path, "deflection_from"))
    return f.choice(*v, join(path, "deflection_from"), {"undeformed", "first_touch"}) == 1
               ? DeflectionOrigin::first_touch
               : DeflectionOrigin::undeformed;
  return DeflectionOrigin::undeformed;
}

// The deepest a support can press, from the study's origin (the first touch is at most ~a few mm off the
// undeformed tyre's, so the section height bounds both).
void check_deflection_below_section(const FieldChecker& c, double deflection, const std::string& path,
                                    const TyreScale& tyre) {
  if (!(deflection < tyre.section_height))
    c.fail(path, fmt::format("must be less than the tyre's section height, {:.1f} mm (outer radius {:.1f} mm − the "
                             "profile's smallest r): deeper, the support would pass the bead (got {:g})",
                             tyre.section_height, tyre.outer_radius, deflection));
}

}  // namespace

LoadCurveStudy read_load_curve(TomlFields& f, const toml::node& n, const std::string& path) {
  const toml::table& t =
      f.table(n, path, {"name", "support", "theory", "max_deflection", "points", "deflection_from"});
  LoadCurveStudy s;
  read_study_name_and_support(f, t, path, s.name, s.support);
  s.linear = read_theory_is_linear(f, t, path);
  f.opt_number(t, path, "max_deflection", s.max_deflection, " (mm)");
  f.opt_integer(t, path, "points", s.points);
  s.deflection_from = read_deflection_from(f, t, path);
  return s;
}

FootprintStudy read_footprint(TomlFields& f, const toml::node& n, const std::string& path) {
  const toml::table& t = f.table(
      n, path, {"name", "support", "theory", "target_load", "load_tolerance", "deflection", "deflection_from"});
  FootprintStudy s;
  read_study_name_and_support(f, t, path, s.name, s.support);
  s.linear = read_theory_is_linear(f, t, path);
  f.opt_number(t, path, "target_load", s.target_load, " (N)");
  f.opt_number(t, path, "load_tolerance", s.load_tolerance, " (relative)");
  if (f.get(t, path, "deflection")) {
    if (f.get(t, path, "target_load"))
      f.fail(join(path, "deflection"),
             "give either target_load (the footprint at a load) or deflection (at a deflection), not both");
    s.deflection = f.req_number(t, path, "deflection", " (mm)");
  }
  s.deflection_from = read_deflection_from(f, t, path);
  return s;
}

void check_file_name(const FieldChecker& c, const std::string& name, const std::string& path,
                     std::string_view allowed_chars, std::string_view allowed, std::string_view what) {
  if (name.empty()) c.fail(path, fmt::format("must not be empty (it names {})", what));
  const bool plain = std::all_of(name.begin(), name.end(), [&](char ch) {
    return (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') ||
           allowed_chars.find(ch) != std::string_view::npos;
  });
  if (!plain) c.fail(path, fmt::format("may contain only {} (got \"{}\")", allowed, name));
  if (name.front() == '.')
    c.fail(path, fmt::format("must not start with '.' (got \"{}\"): it names {}, and \".\", \"..\" and hidden "
                             "names are not plain file names",
                             name, what));
  if (name.size() > static_cast<std::size_t>(kMaxNameLength))
    c.fail(path, fmt::format("must have at most {} characters (got {}): it names {}", kMaxNameLength, name.size(),
                             what));
}

void check_study_name(const FieldChecker& c, const std::string& name, const std::string& path,
                      std::map<std::string, std::string>& seen) {
  check_file_name(c, name, path, "_-", "letters A-Z a-z, digits 0-9, '_' and '-'", "the study's output files");
  if (const auto [it, added] = seen.emplace(name, path); !added)
    c.fail(path,
           fmt::format("duplicate name \"{}\" (already used by {}); load curves, footprints and rolling studies need "
                       "distinct names",
                       name, it->second));
}

void check_load(const FieldChecker& c, double target_load, double load_tolerance, const std::string& path) {
  c.positive(target_load, join(path, "target_load"));
  if (!(target_load <= kMaxTargetLoad))
    c.fail(join(path, "target_load"),
           fmt::format("must be ≤ {:g} N (the plausibility bound for any real tyre; got {:g})", kMaxTargetLoad, target_load));
  c.finite(load_tolerance, join(path, "load_tolerance"));
  if (!(load_tolerance > 0 && load_tolerance < kMaxLoadTolerance))
    c.fail(join(path, "load_tolerance"), fmt::format("must be > 0 and < {} (got {})", kMaxLoadTolerance, load_tolerance));
}

void check_load_curve(const FieldChecker& c, const LoadCurveStudy& s, const std::string& path, const TyreScale& tyre) {
  check_support(c, s.support, join(path, "support"), tyre.outer_radius);
  const std::string dp = join(path, "max_deflection");
  c.positive(s.max_deflection, dp);
  check_deflection_below_section(c, s.max_deflection, dp, tyre);
  c.at_least(s.points, 1, join(path, "points"));
  if (s.points > kMaxLoadCurvePoints)
    c.fail(join(path, "points"), fmt::format("must be ≤ {} (got {})", kMaxLoadCurvePoints, s.points));
}

void check_footprint(const FieldChecker& c, const FootprintStudy& s, const std::string& path, const TyreScale& tyre) {
  check_support(c, s.support, join(path, "support"), tyre.outer_radius);
  check_load(c, s.target_load, s.load_tolerance, path);
  if (s.deflection) {
    const std::string dp = join(path, "deflection");
    c.finite(*s.deflection, dp);
    c.non_negative(*s.deflection, dp);
    check_deflection_below_section(c, *s.deflection, dp, tyre);
  }
}

}  // namespace tirefem::case_reading
