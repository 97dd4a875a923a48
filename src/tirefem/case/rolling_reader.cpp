#include "tirefem/case/rolling_reader.hpp"

#include <fmt/format.h>

#include <map>

#include "tirefem/case/mesh_reader.hpp"
#include "tirefem/case/support_reader.hpp"

namespace tirefem::case_reading {

namespace {

// The keys allowed depend on the state, as for supports.
RollingStateSpec read_state(TomlFields& f, const toml::node& n, const std::string& path) {
  using Kind = RollingStateSpec::Kind;
  f.mark(path, n.source().begin);
  const toml::table* raw = n.as_table();
  if (!raw) f.fail(path, fmt::format("must be a table {{ state = \"free\", ... }} (got {})", type_name(n.type())));
  if (!raw->contains("state"))  // a misspelt state: "did you mean"
    f.table(n, path, {"state", "name", "slip", "rolling_radius", "wheel"});
  RollingStateSpec s;
  s.kind = static_cast<Kind>(
      f.choice(f.need(*raw, path, "state", "\"free\", \"given_slip\", \"given_radius\", \"full_stick\" or \"full_slip\""),
               join(path, "state"), {"free", "given_slip", "given_radius", "full_stick", "full_slip"}));  // enum order
  static constexpr std::string_view kind_names[] = {"free", "given_slip", "given_radius", "full_stick", "full_slip"};
  const std::string_view kind = kind_names[static_cast<int>(s.kind)];
  const std::string_view own = s.kind == Kind::given_slip || s.kind == Kind::full_stick ? "slip"
                               : s.kind == Kind::given_radius                           ? "rolling_radius"
                               : s.kind == Kind::full_slip                              ? "wheel"
                                                                                        : "";
  for (auto&& [k, v] : *raw) {  // a key of another state (typos: table() below)
    if (k.str() == own || (k.str() != "slip" && k.str() != "rolling_radius" && k.str() != "wheel")) continue;
    f.mark(join(path, k.str()), k.source().begin);
    f.fail(join(path, k.str()),
           fmt::format("not allowed in a \"{}\" state (it takes {})", kind,
                       own.empty() ? std::string("only state and name") : fmt::format("state, name and {}", own)));
  }
  const toml::table& t = own.empty() ? f.table(n, path, {"state", "name"}) : f.table(n, path, {"state", "name", own});
  switch (s.kind) {
    case Kind::free:
      s.name = "free";
      break;
    case Kind::given_slip:
      s.slip = f.req_number(t, path, "slip", " (slip κ)");
      s.name = fmt::format("slip_{:g}", s.slip);
      break;
    case Kind::given_radius:
      s.rolling_radius = f.req_number(t, path, "rolling_radius", " (mm)");
      s.name = fmt::format("radius_{:g}", s.rolling_radius);
      break;
    case Kind::full_stick:
      f.opt_number(t, path, "slip", s.slip, " (slip κ)");
      s.name = "full_stick";
      break;
    case Kind::full_slip:
      if (const toml::node* v = f.get(t, path, "wheel"))
        s.braking = f.choice(*v, join(path, "wheel"), {"spinning", "locked"}) == 1;
      s.name = s.braking ? "full_slip_locked" : "full_slip_spinning";
      break;
  }
  if (const toml::node* v = f.get(t, path, "name")) s.name = f.string(*v, join(path, "name"));
  return s;
}

SlipSweep read_sweep(TomlFields& f, const toml::node& n, const std::string& sp) {
  const toml::table& w = f.table(n, sp, {"from", "to", "points", "hold"});
  SlipSweep sw;
  f.opt_number(w, sp, "from", sw.from, " (slip κ)");
  f.opt_number(w, sp, "to", sw.to, " (slip κ)");
  f.opt_integer(w, sp, "points", sw.points);
  if (const toml::node* h = f.get(w, sp, "hold")) sw.hold_load = f.choice(*h, join(sp, "hold"), {"deflection", "load"}) == 1;
  return sw;
}

void check_slip(const FieldChecker& c, double v, const std::string& path) {
  c.finite(v, path);
  if (!(v > -1)) c.fail(path, fmt::format("must be > -1 (got {})", v));
  c.at_most(v, kMaxSlip, path);
}

// κ = Re/Rk − 1 (analysis/rolling.cpp), with Re estimated by the tyre's outer radius R.
void check_rolling_radius(const FieldChecker& c, double rk, const std::string& path, double outer_radius) {
  c.positive(rk, path);
  const double implied = outer_radius / rk - 1.0;
  if (!(implied >= kMinImpliedSlip && implied <= kMaxSlip))
    c.fail(path, fmt::format("implies a slip κ = R/Rk − 1 = {:.9g} with R ≈ {:.1f} mm, the tyre's outer radius "
                             "(the free-rolling radius is close to it); the slip must be in [{}, {}], so Rk in "
                             "[{:.1f}, {:.0f}] mm (a slower wheel is locked: full_slip, wheel = \"locked\"; got {:g})",
                             implied, outer_radius, kMinImpliedSlip, kMaxSlip, outer_radius / (1.0 + kMaxSlip),
                             outer_radius / (1.0 + kMinImpliedSlip), rk));
}

void check_states(const FieldChecker& c, const RollingStudy& s, const std::string& path, const TyreScale& tyre) {
  using Kind = RollingStateSpec::Kind;
  std::map<std::string, std::string> seen;  // state name -> its path
  for (std::size_t k = 0; k < s.states.size(); ++k) {
    const RollingStateSpec& st = s.states[k];
    const std::string p = index(join(path, "states"), k);
    if (st.kind == Kind::given_slip || st.kind == Kind::full_stick) check_slip(c, st.slip, join(p, "slip"));
    if (st.kind == Kind::given_radius) check_rolling_radius(c, st.rolling_radius, join(p, "rolling_radius"), tyre.outer_radius);
    const std::string np = join(p, "name");
    check_file_name(c, st.name, np, "_.+-", "letters A-Z a-z, digits 0-9, '_', '.', '+' and '-'",
                    "the state in tables, plots and the summary");
    if (const auto [it, added] = seen.emplace(st.name, np); !added)
      c.fail(np, fmt::format("duplicate state name \"{}\" (already used by {}); the states of a study need "
                             "distinct names",
                             st.name, it->second));
  }
}

}  // namespace

RollingStudy read_rolling(TomlFields& f, const toml::node& n, const std::string& path, const MeshSettings& case_mesh) {
  const toml::table& t = f.table(
      n, path, {"name", "support", "target_load", "load_tolerance", "friction", "reverse", "states", "sweep", "mesh"});
  RollingStudy s;
  if (const toml::node* v = f.get(t, path, "mesh")) s.mesh = read_mesh(f, *v, join(path, "mesh"), case_mesh);
  read_study_name_and_support(f, t, path, s.name, s.support);
  f.opt_number(t, path, "target_load", s.target_load, " (N)");
  f.opt_number(t, path, "load_tolerance", s.load_tolerance, " (relative)");
  f.opt_number(t, path, "friction", s.friction, " (Coulomb coefficient μ)");
  f.opt_bool(t, path, "reverse", s.reverse);
  if (const toml::node* v = f.get(t, path, "states")) {
    const std::string sp = join(path, "states");
    const toml::array& a = f.array(*v, sp, "states { state = \"free\", ... }");
    for (std::size_t i = 0; i < a.size(); ++i) s.states.push_back(read_state(f, a[i], index(sp, i)));
  }
  if (const toml::node* v = f.get(t, path, "sweep")) s.sweep = read_sweep(f, *v, join(path, "sweep"));
  return s;
}

void check_rolling(const FieldChecker& c, const RollingStudy& s, const std::string& path, const TyreScale& tyre) {
  const std::string sp = join(path, "support");
  check_support(c, s.support, sp, tyre.outer_radius);
  // The steady state is frozen in the road's frame: the road must look the same all along y.
  if (s.support.kind == SupportDescription::Kind::surface)
    for (std::size_t j = 0; j < s.support.terms.size(); ++j)
      if (const SupportDescription::Term& t = s.support.terms[j]; t.y_power > 0 && t.coefficient != 0.0)
        c.fail(join(index(join(sp, "terms"), j), "y_power"),
               fmt::format("must be 0 where the coefficient is not (got {}): steady rolling needs a road that "
                           "does not change along y",
                           t.y_power));
  check_load(c, s.target_load, s.load_tolerance, path);
  c.positive(s.friction, join(path, "friction"));
  c.at_most(s.friction, kMaxFriction, join(path, "friction"));
  if (s.states.empty() && !s.sweep)
    c.fail(path, "needs states or a sweep (states = [{ state = \"free\" }, ...] or sweep = { from, to, points })");
  check_states(c, s, path, tyre);
  if (s.sweep) {
    const std::string wp = join(path, "sweep");
    check_slip(c, s.sweep->from, join(wp, "from"));
    check_slip(c, s.sweep->to, join(wp, "to"));
    if (!(s.sweep->from < s.sweep->to))
      c.fail(join(wp, "to"), fmt::format("must be greater than from = {} (got {})", s.sweep->from, s.sweep->to));
    c.int_range(s.sweep->points, 2, kMaxSweepPoints, join(wp, "points"));
  }
}

}  // namespace tirefem::case_reading
