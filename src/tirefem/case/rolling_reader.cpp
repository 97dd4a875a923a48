#include "tirefem/case/rolling_reader.hpp"

#include <fmt/format.h>

#include <cmath>
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
  // Slip angle and camber go with every state but full slip (whose traction direction they would change).
  const bool cornering = s.kind != Kind::full_slip;
  std::vector<std::string> keys{"state", "name"};
  if (!own.empty()) keys.emplace_back(own);
  if (cornering) keys.insert(keys.end(), {"slip_angle", "camber", "hold"});
  std::string allowed = keys.front();
  for (std::size_t i = 1; i < keys.size(); ++i) allowed += (i + 1 == keys.size() ? " and " : ", ") + keys[i];
  for (auto&& [k, v] : *raw) {  // a key of another state (typos: table() below)
    const bool angle = k.str() == "slip_angle" || k.str() == "camber" || k.str() == "hold";
    if (k.str() == own || (angle && cornering) ||
        (!angle && k.str() != "slip" && k.str() != "rolling_radius" && k.str() != "wheel"))
      continue;
    f.mark(join(path, k.str()), k.source().begin);
    f.fail(join(path, k.str()),
           fmt::format("not allowed in a \"{}\" state (it takes {})", kind, allowed));
  }
  const toml::table& t = own.empty() ? f.table(n, path, {"state", "name", "slip_angle", "camber", "hold"})
                         : cornering ? f.table(n, path, {"state", "name", own, "slip_angle", "camber", "hold"})
                                     : f.table(n, path, {"state", "name", own});
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
  if (cornering) {
    f.opt_number(t, path, "slip_angle", s.slip_angle_deg, " (degrees)");
    f.opt_number(t, path, "camber", s.camber_deg, " (degrees)");
    if (s.slip_angle_deg != 0.0) s.name += fmt::format("_alpha_{:g}", s.slip_angle_deg);
    if (s.camber_deg != 0.0) s.name += fmt::format("_camber_{:g}", s.camber_deg);
    if (const toml::node* h = f.get(t, path, "hold")) s.hold_load = f.choice(*h, join(path, "hold"), {"deflection", "load"}) == 1;
  }
  if (const toml::node* v = f.get(t, path, "name")) s.name = f.string(*v, join(path, "name"));
  return s;
}

SlipAngleSweep read_angle_sweep(TomlFields& f, const toml::node& n, const std::string& sp) {
  const toml::table& w = f.table(n, sp, {"from", "to", "points", "hold", "slip", "camber", "mirror"});
  SlipAngleSweep sw;
  f.opt_bool(w, sp, "mirror", sw.mirror_negative_angles);
  f.opt_number(w, sp, "from", sw.from, " (slip angle, degrees)");
  f.opt_number(w, sp, "to", sw.to, " (slip angle, degrees)");
  f.opt_integer(w, sp, "points", sw.points);
  f.opt_number(w, sp, "slip", sw.slip, " (slip κ)");
  f.opt_number(w, sp, "camber", sw.camber_deg, " (degrees)");
  if (const toml::node* h = f.get(w, sp, "hold")) sw.hold_load = f.choice(*h, join(sp, "hold"), {"deflection", "load"}) == 1;
  return sw;
}

CombinedSlipGrid read_combined(TomlFields& f, const toml::node& n, const std::string& sp) {
  const toml::table& w = f.table(n, sp, {"slips", "slip_angles", "hold"});
  CombinedSlipGrid g;
  g.slips = f.numbers(f.need(w, sp, "slips", "an array of slips κ"), join(sp, "slips"), " (slip κ)");
  g.slip_angles_deg = f.numbers(f.need(w, sp, "slip_angles", "an array of slip angles (degrees)"),
                                join(sp, "slip_angles"), " (degrees)");
  if (const toml::node* h = f.get(w, sp, "hold")) g.hold_load = f.choice(*h, join(sp, "hold"), {"deflection", "load"}) == 1;
  return g;
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
    check_angle(c, st.slip_angle_deg, join(p, "slip_angle"), kMaxSlipAngleDeg);
    check_angle(c, st.camber_deg, join(p, "camber"), kMaxCamberDeg);
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

void check_slip(const FieldChecker& c, double v, const std::string& path) {
  c.finite(v, path);
  if (!(v > -1)) c.fail(path, fmt::format("must be > -1 (got {})", v));
  c.at_most(v, kMaxSlip, path);
}

void check_angle(const FieldChecker& c, double degrees, const std::string& path, double largest) {
  c.finite(degrees, path);
  if (!(std::abs(degrees) <= largest))
    c.fail(path, fmt::format("must be within ±{} degrees (got {})", largest, degrees));
}

RollingStudy read_rolling(TomlFields& f, const toml::node& n, const std::string& path, const MeshSettings& case_mesh) {
  const toml::table& t = f.table(
      n, path, {"name", "support", "target_load", "load_tolerance", "friction", "reverse", "states", "sweep",
                "angle_sweep", "combined", "tread_shear", "mesh"});
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
  if (const toml::node* v = f.get(t, path, "angle_sweep"))
    s.angle_sweep = read_angle_sweep(f, *v, join(path, "angle_sweep"));
  if (const toml::node* v = f.get(t, path, "combined")) s.combined = read_combined(f, *v, join(path, "combined"));
  if (const toml::node* v = f.get(t, path, "tread_shear"))
    s.tread_shear = static_cast<RollingStudy::TreadShear>(
        f.choice(*v, join(path, "tread_shear"), {"longitudinal", "planar"}));  // enum order
  return s;
}

void check_rolling(const FieldChecker& c, const RollingStudy& s, const std::string& path, const TyreScale& tyre,
                   bool case_half_model) {
  const bool mesh_is_half = s.mesh ? s.mesh->half_model : case_half_model;
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
  if (s.states.empty() && !s.sweep && !s.angle_sweep && !s.combined)
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
  if (s.angle_sweep) {
    const std::string wp = join(path, "angle_sweep");
    check_angle(c, s.angle_sweep->from, join(wp, "from"), kMaxSlipAngleDeg);
    check_angle(c, s.angle_sweep->to, join(wp, "to"), kMaxSlipAngleDeg);
    if (!(s.angle_sweep->from < s.angle_sweep->to))
      c.fail(join(wp, "to"), fmt::format("must be greater than from = {} (got {})", s.angle_sweep->from, s.angle_sweep->to));
    c.int_range(s.angle_sweep->points, 2, kMaxSweepPoints, join(wp, "points"));
    check_slip(c, s.angle_sweep->slip, join(wp, "slip"));
    check_angle(c, s.angle_sweep->camber_deg, join(wp, "camber"), kMaxCamberDeg);
  }
  if (s.combined) {
    const std::string gp = join(path, "combined");
    if (s.combined->slips.empty()) c.fail(join(gp, "slips"), "must list at least one slip κ");
    if (s.combined->slip_angles_deg.empty()) c.fail(join(gp, "slip_angles"), "must list at least one slip angle");
    if (s.combined->slips.size() * s.combined->slip_angles_deg.size() > static_cast<std::size_t>(kMaxSweepPoints))
      c.fail(gp, fmt::format("at most {} (κ, α) points (got {} × {})", kMaxSweepPoints, s.combined->slips.size(),
                             s.combined->slip_angles_deg.size()));
    for (std::size_t k = 0; k < s.combined->slips.size(); ++k) check_slip(c, s.combined->slips[k], index(join(gp, "slips"), k));
    for (std::size_t k = 0; k < s.combined->slip_angles_deg.size(); ++k)
      check_angle(c, s.combined->slip_angles_deg[k], index(join(gp, "slip_angles"), k), kMaxSlipAngleDeg);
  }
  // Slip angle and camber break the symmetry about the equatorial plane; camber tilts a plane road.
  const auto cornering = [&](double alpha, double gamma, const std::string& where) {
    if ((alpha != 0.0 || gamma != 0.0) && mesh_is_half)
      c.fail(where, "needs the full model (bead to bead): give the study mesh = { half_model = false, ... }");
    if ((alpha != 0.0 || gamma != 0.0) && s.tread_shear == RollingStudy::TreadShear::longitudinal)
      c.fail(where, "needs tread_shear = \"planar\" (the longitudinal shear has no lateral component)");
    if (gamma != 0.0 && s.support.kind != SupportDescription::Kind::plane)
      c.fail(where, "camber is supported on a plane support only");
  };
  for (std::size_t k = 0; k < s.states.size(); ++k) {
    const std::string p = index(join(path, "states"), k);
    cornering(s.states[k].slip_angle_deg, 0.0, join(p, "slip_angle"));
    cornering(0.0, s.states[k].camber_deg, join(p, "camber"));
  }
  if (s.angle_sweep) {
    cornering(1.0, 0.0, join(path, "angle_sweep"));
    cornering(0.0, s.angle_sweep->camber_deg, join(join(path, "angle_sweep"), "camber"));
  }
  if (s.combined) cornering(1.0, 0.0, join(path, "combined"));
}

}  // namespace tirefem::case_reading
