#include "tirefem/case/support_reader.hpp"

#include <fmt/format.h>

namespace tirefem::case_reading {

// The keys allowed depend on the kind.
SupportDescription read_support(TomlFields& f, const toml::node& n, const std::string& path) {
  using Kind = SupportDescription::Kind;
  f.mark(path, n.source().begin);
  const toml::table* raw = n.as_table();
  if (!raw)
    f.fail(path, fmt::format("must be a table {{ kind = \"plane\", \"drum\" or \"surface\", ... }} (got {})",
                             type_name(n.type())));
  if (!raw->contains("kind")) f.table(n, path, {"kind", "diameter", "terms"});  // a misspelt kind: "did you mean"
  SupportDescription s;
  s.kind = static_cast<Kind>(f.choice(f.need(*raw, path, "kind", "\"plane\", \"drum\" or \"surface\""),
                                      join(path, "kind"), {"plane", "drum", "surface"}));  // enum order
  static constexpr std::string_view kind_names[] = {"plane", "drum", "surface"};
  const std::string_view kind = kind_names[static_cast<int>(s.kind)];
  for (auto&& [k, v] : *raw) {  // a key of another kind: say which kind it belongs to
    const Kind owner = k.str() == "diameter" ? Kind::drum : k.str() == "terms" ? Kind::surface : s.kind;
    if (owner == s.kind) continue;
    f.mark(join(path, k.str()), k.source().begin);
    f.fail(join(path, k.str()),
           fmt::format("not allowed for kind \"{}\" ({} belongs to kind \"{}\"; a {} support takes {})", kind, k.str(),
                       kind_names[static_cast<int>(owner)], kind,
                       s.kind == Kind::plane  ? "no other keys"
                       : s.kind == Kind::drum ? "diameter"
                                              : "terms"));
  }
  if (s.kind == Kind::plane) {
    f.table(n, path, {"kind"});
  } else if (s.kind == Kind::drum) {
    const toml::table& t = f.table(n, path, {"kind", "diameter"});
    s.drum_diameter = f.req_number(t, path, "diameter", " (mm, the drum's outer diameter)");
  } else {
    const toml::table& t = f.table(n, path, {"kind", "terms"});
    const std::string tp = join(path, "terms");
    const toml::array& a = f.array(f.need(t, path, "terms",
                                          "an array of terms { coefficient, x_power, y_power }, z = Σ coefficient "
                                          "· x^x_power · y^y_power (mm)"),
                                   tp, "terms { coefficient, x_power, y_power }");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = index(tp, i);
      const toml::table& term = f.table(a[i], p, {"coefficient", "x_power", "y_power"});
      SupportDescription::Term tm;
      tm.coefficient = f.req_number(term, p, "coefficient", " (mm^(1 - x_power - y_power))");
      f.opt_integer(term, p, "x_power", tm.x_power);
      f.opt_integer(term, p, "y_power", tm.y_power);
      s.terms.push_back(tm);
    }
  }
  return s;
}

void check_support(const FieldChecker& c, const SupportDescription& s, const std::string& path, double tyre_radius) {
  if (s.kind == SupportDescription::Kind::drum) {
    const std::string dp = join(path, "diameter");
    c.positive(s.drum_diameter, dp);
    if (!(s.drum_diameter >= 2.0 * tyre_radius))
      c.fail(dp, fmt::format("must be at least the tyre's outer diameter, 2 × {:.1f} = {:.1f} mm (a test drum is "
                             "not smaller than the tyre; got {:g})",
                             tyre_radius, 2.0 * tyre_radius, s.drum_diameter));
    if (!(s.drum_diameter <= kMaxDrumDiameter))
      c.fail(dp, fmt::format("must be ≤ {:g} mm (100 m; a larger drum is a plane: use {{ kind = \"plane\" }}; got "
                             "{:g})",
                             kMaxDrumDiameter, s.drum_diameter));
  }
  if (s.kind != SupportDescription::Kind::surface) return;
  const std::string tp = join(path, "terms");
  if (s.terms.empty()) c.fail(tp, "a surface needs at least one term { coefficient, x_power, y_power }");
  for (std::size_t i = 0; i < s.terms.size(); ++i) {
    const SupportDescription::Term& t = s.terms[i];
    const std::string p = index(tp, i);
    c.finite(t.coefficient, join(p, "coefficient"));
    c.int_range(t.x_power, 0, kMaxSurfacePower, join(p, "x_power"));
    c.int_range(t.y_power, 0, kMaxSurfacePower, join(p, "y_power"));
    if (t.x_power == 0 && t.y_power == 0 && t.coefficient != 0.0)
      c.fail(join(p, "coefficient"),
             fmt::format("a constant term (x_power = y_power = 0) must be zero (got {}): the road must pass "
                         "through the origin, where the undeformed tyre touches it",
                         t.coefficient));
  }
}

}  // namespace tirefem::case_reading
