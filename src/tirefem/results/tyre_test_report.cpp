#include "tirefem/results/tyre_test_report.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace tirefem {
namespace {
constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
const double kNaN = std::nan("");

const TyreTestLoad* load_of(const TyreTestResult& t, double target) {
  for (const TyreTestLoad& l : t.loads)
    if (l.target_load_N == target) return &l;
  return nullptr;
}

// One curve per load of the rows of `kind`: x and y taken from the row.
template <class X, class Y>
std::vector<PlotSeries> per_load(const TyreTestResult& t, TyreTestRow::Kind kind, X x, Y y) {
  std::vector<PlotSeries> series;
  for (const TyreTestLoad& l : t.loads) {
    PlotSeries s{fmt::format("Fz {:.0f} N", l.target_load_N), {}, {}, "linespoints pt 7"};
    for (const TyreTestRow& r : t.rows)
      if (r.kind == kind && r.target_load_N == l.target_load_N) s.x.push_back(x(r)), s.y.push_back(y(r));
    if (!s.x.empty()) series.push_back(std::move(s));
  }
  return series;
}
}  // namespace

CsvTable tyre_test_table(const TyreTestResult& t) {
  CsvTable table;
  table.comments = {
      fmt::format("tirefem: virtual flat-track test '{}', FNOMIN {:.0f} N, unloaded radius {:.4f} m", t.name,
                  t.nominal_load_N, t.unloaded_radius_mm * 1e-3),
      "TYDEX / ISO 8855 W axes at the contact centre: FX along the heading, FY to the left, FZ up, MX overturning, MZ "
      "aligning; ALPHA > 0 gives FY < 0; GAMMA > 0 leans the top of the wheel to the right",
      "units: FZ FX FY N; KAPPA -; ALPHA GAMMA rad; MX MZ N*m; RE RL PATCH_LENGTH PATCH_WIDTH m; TIME s",
      "RE: effective rolling radius of free rolling at the load; RL: loaded radius (axle above the road) at the "
      "point; PATCH_*: the static footprint at the load",
      "SERIES: 0 free rolling, 1 longitudinal slip sweep, 2 slip-angle sweep, 3 cambered free rolling; FZ held at "
      "TARGET_FZ in the sweeps"};
  table.columns = {"FZ", "KAPPA", "ALPHA", "GAMMA", "FX", "FY", "MZ", "MX", "RE", "RL", "PATCH_LENGTH",
                   "PATCH_WIDTH", "TARGET_FZ", "SERIES", "NEWTON_ITERATIONS", "FACTORIZATIONS", "TIME"};
  for (const TyreTestRow& r : t.rows) {
    const TyreTestLoad* l = load_of(t, r.target_load_N);
    table.rows.push_back({r.Fz_N, r.kappa, r.alpha_rad, r.gamma_rad, r.Fx_N, r.Fy_N, r.Mz_Nm, r.Mx_Nm,
                          r.effective_radius_m, r.loaded_radius_m, l ? l->patch_length_mm * 1e-3 : kNaN,
                          l ? l->patch_width_mm * 1e-3 : kNaN, r.target_load_N, static_cast<double>(r.kind),
                          static_cast<double>(r.newton_iterations), static_cast<double>(r.factorizations),
                          r.time_s});
  }
  return table;
}

CsvTable tyre_test_vertical_table(const TyreTestResult& t) {
  CsvTable table;
  table.comments = {fmt::format("tirefem: load-deflection curve of '{}' on a plane (half model, full-tyre "
                                "figures), deflection from the undeformed tyre",
                                t.name)};
  table.columns = {"deflection_mm", "Qz_N", "loaded_radius_mm", "patch_length_mm", "patch_width_mm"};
  if (!t.vertical) return table;
  for (const LoadPoint& p : t.vertical->points)
    table.rows.push_back({p.deflection_mm, p.patch.Qz_N, t.unloaded_radius_mm - p.deflection_mm,
                          p.patch.patch_length_mm, p.patch.patch_width_mm});
  return table;
}

Plot tyre_test_fx_plot(const TyreTestResult& t) {
  Plot p{fmt::format("{}: longitudinal force (W axes, Fz held)", t.name), "longitudinal slip κ [-]", "FX [N]", {}};
  p.series = per_load(t, TyreTestRow::Kind::slip_sweep, [](const TyreTestRow& r) { return r.kappa; },
                      [](const TyreTestRow& r) { return r.Fx_N; });
  return p;
}

Plot tyre_test_fy_plot(const TyreTestResult& t) {
  Plot p{fmt::format("{}: lateral force (W axes, Fz held)", t.name), "slip angle α [deg]", "FY [N]", {}};
  p.series = per_load(t, TyreTestRow::Kind::angle_sweep, [](const TyreTestRow& r) { return r.alpha_rad * kDegreesPerRadian; },
                      [](const TyreTestRow& r) { return r.Fy_N; });
  return p;
}

Plot tyre_test_mz_plot(const TyreTestResult& t) {
  Plot p{fmt::format("{}: aligning moment (W axes, Fz held)", t.name), "slip angle α [deg]", "MZ [N·m]", {}};
  p.series = per_load(t, TyreTestRow::Kind::angle_sweep, [](const TyreTestRow& r) { return r.alpha_rad * kDegreesPerRadian; },
                      [](const TyreTestRow& r) { return r.Mz_Nm; });
  return p;
}

Plot tyre_test_vertical_plot(const TyreTestResult& t) {
  Plot p{fmt::format("{}: vertical characteristic on a plane", t.name), "deflection δz [mm]", "Fz [N]", {}};
  PlotSeries curve{"load-deflection curve", {}, {}, "linespoints pt 7"};
  if (t.vertical)
    for (const LoadPoint& q : t.vertical->points) curve.x.push_back(q.deflection_mm), curve.y.push_back(q.patch.Qz_N);
  PlotSeries rig{"footprints of the test loads", {}, {}, "points pt 6 ps 2"};
  for (const TyreTestLoad& l : t.loads)
    if (l.Fz_N > 0) rig.x.push_back(l.deflection_mm), rig.y.push_back(l.Fz_N);
  p.series = {std::move(curve), std::move(rig)};
  return p;
}

toml::table tyre_test_summary(const TyreTestResult& t) {
  toml::array loads;
  for (const TyreTestLoad& l : t.loads) {
    toml::table e{{"target_load_N", l.target_load_N}, {"completed", l.completed}};
    if (!l.failure.empty()) e.insert("failure", l.failure);
    e.insert("Fz_N", l.Fz_N);
    e.insert("deflection_mm", l.deflection_mm);
    e.insert("loaded_radius_mm", l.loaded_radius_mm);
    if (l.effective_rolling_radius_mm) e.insert("effective_rolling_radius_mm", *l.effective_rolling_radius_mm);
    e.insert("patch_length_mm", l.patch_length_mm);
    e.insert("patch_width_mm", l.patch_width_mm);
    if (l.slip_stiffness_N) e.insert("slip_stiffness_N", *l.slip_stiffness_N);
    if (l.cornering_stiffness_N_per_deg) e.insert("cornering_stiffness_N_per_deg", *l.cornering_stiffness_N_per_deg);
    if (l.pneumatic_trail_mm) e.insert("pneumatic_trail_mm", *l.pneumatic_trail_mm);
    loads.push_back(std::move(e));
  }
  toml::table s{{"name", t.name},
                {"nominal_load_N", t.nominal_load_N},
                {"unloaded_radius_mm", t.unloaded_radius_mm},
                {"completed", t.completed},
                {"points", static_cast<int64_t>(t.rows.size())},
                {"table", t.name + "/tyre_test.csv"},
                {"loads", std::move(loads)}};
  if (!t.failures.empty()) {
    toml::array f;
    for (const std::string& m : t.failures) f.push_back(m);
    s.insert("failures", std::move(f));
  }
  return s;
}

}  // namespace tirefem
