#include "tirefem/case/tread_reader.hpp"

#include <fmt/format.h>

#include "tirefem/case/case_reader.hpp"
#include "tirefem/tyre/meridian_profile.hpp"

namespace tirefem::case_reading {

namespace {

Table read_table_in_s(TomlFields& f, const toml::node& n, const std::string& path, std::string_view unit) {
  if (n.is_number()) return Table::constant(f.number(n, path, unit));
  if (!n.is_table())
    f.fail(path, fmt::format("must be a number or a table {{ s = [...], value = [...] }} (got {})",
                             type_name(n.type())));
  const toml::table& t = f.table(n, path, {"s", "value"});
  Table tab;
  tab.s = f.numbers(f.need(t, path, "s", "an array of arc lengths (mm)"), join(path, "s"), " (mm)");
  tab.value = f.numbers(f.need(t, path, "value", "an array of numbers"), join(path, "value"), unit);
  return tab;
}

}  // namespace

bool read_interlayer_and_tread(TomlFields& f, const toml::table& tyre, const std::string& tyre_path,
                               TyreDescription& d) {
  const std::string ip = join(tyre_path, "interlayer");
  const toml::table& il = f.table(f.need(tyre, tyre_path, "interlayer", "a table with thickness"), ip, {"thickness"});
  d.interlayer_thickness = read_table_in_s(
      f, f.need(il, ip, "thickness", "a number or { s = [...], value = [...] } (mm)"), join(ip, "thickness"), " (mm)");

  const std::string tp = join(tyre_path, "tread");
  const toml::table& tr = f.table(f.need(tyre, tyre_path, "tread", "a table [tyre.tread]"), tp,
                                  {"height", "end_s", "stiffness", "shear_modulus"});
  d.tread_height = read_table_in_s(f, f.need(tr, tp, "height", "a number or { s = [...], value = [...] } (mm)"),
                                   join(tp, "height"), " (mm)");
  d.tread_end_s = f.req_number(tr, tp, "end_s", " (mm of arc length from the equator)");
  d.tread_stiffness = f.req_number(tr, tp, "stiffness", " (N/mm³)");
  const toml::node* g = f.get(tr, tp, "shear_modulus");
  if (g) d.tread_shear_modulus = f.number(*g, join(tp, "shear_modulus"), " (MPa)");
  return g != nullptr;
}

void check_table(const FieldChecker& c, const Table& t, const std::string& path, const Bound& bound) {
  if (t.s.empty()) c.fail(join(path, "s"), "must have at least one entry");
  if (t.s.size() != t.value.size())
    c.fail(join(path, "value"), fmt::format("must have as many entries as s ({}; got {})", t.s.size(), t.value.size()));
  for (std::size_t i = 0; i < t.s.size(); ++i) {
    c.finite(t.s[i], index(join(path, "s"), i));
    if (i > 0 && !(t.s[i] > t.s[i - 1]))
      c.fail(index(join(path, "s"), i),
             fmt::format("must be greater than s[{}] = {} (got {})", i - 1, t.s[i - 1], t.s[i]));
    c.plausible(t.value[i], bound, index(join(path, "value"), i));
  }
}

void check_interlayer_fold(const FieldChecker& c, const TyreDescription& t, const std::string& path) {
  constexpr int kSamplesPerSegment = 8;
  const MeridianProfile profile(t.profile);
  const std::vector<double>& knot_s = profile.point_arc_lengths();
  for (std::size_t k = 0; k + 1 < knot_s.size(); ++k)
    for (int j = 0; j <= kSamplesPerSegment; ++j) {
      const double s = knot_s[k] + (knot_s[k + 1] - knot_s[k]) * j / kSamplesPerSegment;
      const double kappa = profile.curvature(s), h = t.interlayer_thickness.at(s);
      if (kappa < 0 && h * -kappa >= 1.0)
        c.fail(path, fmt::format("h = {:.3g} mm at s = {:.1f} mm (between points[{}] and points[{}] of the profile) is "
                                 "not less than the radius of curvature, {:.3g} mm, of the carcass line's concave bend "
                                 "there: the outer face would fold over (a thinner interlayer or a gentler bend)",
                                 h, s, k, k + 1, -1.0 / kappa));
    }
}

void check_interlayer_and_tread(const FieldChecker& c, const TyreDescription& t, double length, bool rolls) {
  check_table(c, t.interlayer_thickness, "tyre.interlayer.thickness", kThickness);
  check_interlayer_fold(c, t, "tyre.interlayer.thickness");
  check_table(c, t.tread_height, "tyre.tread.height", kTreadHeight);
  c.in_range(t.tread_end_s, 0.0, length + kZoneEndTolerance, "tyre.tread.end_s");
  c.plausible(t.tread_stiffness, kTreadStiffness, "tyre.tread.stiffness");
  if (rolls || t.tread_shear_modulus != 0.0) c.plausible(t.tread_shear_modulus, kModulus, "tyre.tread.shear_modulus");
}

}  // namespace tirefem::case_reading
