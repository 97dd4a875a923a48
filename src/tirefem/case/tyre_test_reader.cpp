#include "tirefem/case/tyre_test_reader.hpp"

#include <fmt/format.h>

#include "tirefem/case/mesh_reader.hpp"
#include "tirefem/case/plausibility_bounds.hpp"
#include "tirefem/case/rolling_reader.hpp"

namespace tirefem::case_reading {

namespace {
// { from, to, points, spacing } of a rig's sweep into its fields (absent keys keep their defaults).
void read_sweep_range(TomlFields& f, const toml::node& n, const std::string& path, std::string_view unit,
                      double& from, double& to, int& points, SweepSpacing& spacing) {
  const toml::table& w = f.table(n, path, {"from", "to", "points", "spacing"});
  f.opt_number(w, path, "from", from, unit);
  f.opt_number(w, path, "to", to, unit);
  f.opt_integer(w, path, "points", points);
  if (const toml::node* x = f.get(w, path, "spacing"))
    spacing = static_cast<SweepSpacing>(f.choice(*x, join(path, "spacing"), {"even", "quadratic"}));  // enum order
}
}  // namespace

TyreTestStudy read_tyre_test(TomlFields& f, const toml::node& n, const std::string& path, const MeshSettings& case_mesh) {
  const toml::table& t = f.table(n, path, {"name", "nominal_load", "loads", "load_tolerance", "friction", "slip_sweep",
                                           "angle_sweep", "cambers", "combined", "vertical", "mesh"});
  TyreTestStudy s;
  s.name = f.string(f.need(t, path, "name", "a string (the study's name)"), join(path, "name"));
  if (const toml::node* v = f.get(t, path, "mesh")) s.mesh = read_mesh(f, *v, join(path, "mesh"), case_mesh);
  f.opt_number(t, path, "nominal_load", s.nominal_load, " (N)");
  if (const toml::node* v = f.get(t, path, "loads"))
    s.load_factors = f.numbers(*v, join(path, "loads"), " (multiples of nominal_load)");
  f.opt_number(t, path, "load_tolerance", s.load_tolerance, " (relative)");
  f.opt_number(t, path, "friction", s.friction, " (Coulomb coefficient μ)");
  if (const toml::node* v = f.get(t, path, "slip_sweep"))
    read_sweep_range(f, *v, join(path, "slip_sweep"), " (slip κ)", s.slip_sweep.from, s.slip_sweep.to,
                     s.slip_sweep.points, s.slip_sweep.spacing);
  if (const toml::node* v = f.get(t, path, "angle_sweep"))
    read_sweep_range(f, *v, join(path, "angle_sweep"), " (slip angle, degrees)", s.angle_sweep.from,
                     s.angle_sweep.to, s.angle_sweep.points, s.angle_sweep.spacing);
  if (const toml::node* v = f.get(t, path, "cambers")) s.cambers_deg = f.numbers(*v, join(path, "cambers"), " (degrees)");
  if (const toml::node* v = f.get(t, path, "combined")) {
    const std::string sp = join(path, "combined");
    const toml::table& w = f.table(*v, sp, {"slips", "slip_angles"});
    CombinedSlipGrid g;
    g.slips = f.numbers(f.need(w, sp, "slips", "an array of slips κ"), join(sp, "slips"), " (slip κ)");
    g.slip_angles_deg = f.numbers(f.need(w, sp, "slip_angles", "an array of slip angles (degrees)"),
                                  join(sp, "slip_angles"), " (degrees)");
    g.hold_load = true;
    s.combined = std::move(g);
  }
  if (const toml::node* v = f.get(t, path, "vertical")) {
    const std::string sp = join(path, "vertical");
    const toml::table& w = f.table(*v, sp, {"max_deflection", "points"});
    f.opt_number(w, sp, "max_deflection", s.vertical_max_deflection, " (mm)");
    f.opt_integer(w, sp, "points", s.vertical_points);
  }
  return s;
}

void check_tyre_test(const FieldChecker& c, const TyreTestStudy& s, const std::string& path, const TyreScale& tyre,
                     bool case_half_model) {
  if (s.mesh ? s.mesh->half_model : case_half_model)
    c.fail(s.mesh ? join(join(path, "mesh"), "half_model") : path,
           "a tyre test needs the full model (bead to bead) for its slip angles: give the study mesh = { half_model "
           "= false, ... }");
  const std::string np = join(path, "nominal_load");
  c.positive(s.nominal_load, np);
  c.at_most(s.nominal_load, kMaxTargetLoad, np);
  c.finite(s.load_tolerance, join(path, "load_tolerance"));
  if (!(s.load_tolerance > 0 && s.load_tolerance < kMaxLoadTolerance))
    c.fail(join(path, "load_tolerance"),
           fmt::format("must be > 0 and < {} (got {})", kMaxLoadTolerance, s.load_tolerance));
  const std::string lp = join(path, "loads");
  if (s.load_factors.empty()) c.fail(lp, "must list at least one load (multiples of nominal_load)");
  if (s.load_factors.size() > 10) c.fail(lp, fmt::format("at most 10 loads (got {})", s.load_factors.size()));
  for (std::size_t k = 0; k < s.load_factors.size(); ++k) {
    const std::string p = index(lp, k);
    c.positive(s.load_factors[k], p);
    c.at_most(s.load_factors[k], 3.0, p);
    if (k > 0 && !(s.load_factors[k] > s.load_factors[k - 1]))
      c.fail(p, fmt::format("must be greater than the load before ({}): loads in increasing order (got {})",
                            s.load_factors[k - 1], s.load_factors[k]));
  }
  c.positive(s.friction, join(path, "friction"));
  c.at_most(s.friction, kMaxFriction, join(path, "friction"));
  const std::string kp = join(path, "slip_sweep");
  check_slip(c, s.slip_sweep.from, join(kp, "from"));
  check_slip(c, s.slip_sweep.to, join(kp, "to"));
  if (!(s.slip_sweep.from < s.slip_sweep.to))
    c.fail(join(kp, "to"), fmt::format("must be greater than from = {} (got {})", s.slip_sweep.from, s.slip_sweep.to));
  c.int_range(s.slip_sweep.points, 3, kMaxSweepPoints, join(kp, "points"));
  const std::string ap = join(path, "angle_sweep");
  check_angle(c, s.angle_sweep.from, join(ap, "from"), kMaxSlipAngleDeg);
  check_angle(c, s.angle_sweep.to, join(ap, "to"), kMaxSlipAngleDeg);
  if (!(s.angle_sweep.from < s.angle_sweep.to))
    c.fail(join(ap, "to"), fmt::format("must be greater than from = {} (got {})", s.angle_sweep.from, s.angle_sweep.to));
  c.int_range(s.angle_sweep.points, 3, kMaxSweepPoints, join(ap, "points"));
  for (std::size_t k = 0; k < s.cambers_deg.size(); ++k)
    check_angle(c, s.cambers_deg[k], index(join(path, "cambers"), k), kMaxCamberDeg);
  if (s.combined) {
    const std::string gp = join(path, "combined");
    // Combined points have both slips: a zero one is a pure-slip point, which the sweeps give already.
    for (std::size_t k = 0; k < s.combined->slips.size(); ++k) {
      const std::string p = index(join(gp, "slips"), k);
      check_slip(c, s.combined->slips[k], p);
      if (s.combined->slips[k] == 0) c.fail(p, "must not be 0 (κ = 0 is the α sweep's)");
    }
    for (std::size_t k = 0; k < s.combined->slip_angles_deg.size(); ++k) {
      const std::string p = index(join(gp, "slip_angles"), k);
      check_angle(c, s.combined->slip_angles_deg[k], p, kMaxSlipAngleDeg);
      if (s.combined->slip_angles_deg[k] == 0) c.fail(p, "must not be 0 (α = 0 is the κ sweep's)");
    }
    if (s.combined->slips.size() < 2) c.fail(join(gp, "slips"), "must list at least two slips κ");
    if (s.combined->slip_angles_deg.size() < 2) c.fail(join(gp, "slip_angles"), "must list at least two slip angles");
    if (s.combined->slips.size() * s.combined->slip_angles_deg.size() > static_cast<std::size_t>(kMaxSweepPoints))
      c.fail(gp, fmt::format("at most {} (κ, α) points (got {} × {})", kMaxSweepPoints, s.combined->slips.size(),
                             s.combined->slip_angles_deg.size()));
  }
  LoadCurveStudy vertical;
  vertical.max_deflection = s.vertical_max_deflection;
  vertical.points = s.vertical_points;
  check_load_curve(c, vertical, join(path, "vertical"), tyre);
}

}  // namespace tirefem::case_reading
