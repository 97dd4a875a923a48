#include "tirefem/report/cornering_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include <fmt/format.h>

#include "tirefem/report/rim_flange_report.hpp"
#include "tirefem/road/support_surface.hpp"

namespace tirefem {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

CsvTable points_table(const RollingResult& r, const std::vector<SweepPoint>& points, const std::string& what) {
  CsvTable t;
  t.comments = {
      fmt::format("tirefem: {} of '{}' ({}, mu = {:g}; converged points)", what, r.name, support_label(r.support),
                  r.friction),
      "W-axis system (ISO 8855 / TYDEX) at the contact centre: X along the travel, Y to the left, Z up from "
      "the road; forces and moments of the road on the tyre; slip angle > 0: the wheel moves to the left of "
      "its heading (Fy < 0); camber > 0: the top of the wheel leans to the right",
      "slip kappa = Re/Rk - 1; pneumatic_trail = -Mz/Fy (nan where |Fy| <= 1e-3 Fz)"};
  if (std::any_of(points.begin(), points.end(), [](const SweepPoint& p) { return p.mirrored; }))
    t.comments.push_back("points at negative slip angle with 0 Newton iterations are the mirror images of those at "
                         "the positive one, not solved (the tyre is its own mirror image, camber 0)");
  t.columns = {"slip_angle_deg", "camber_deg", "slip", "rolling_radius_mm", "deflection_mm", "Fx_N", "Fy_N",
               "Fz_N", "Mz_Nmm", "overturning_moment_Nmm", "pneumatic_trail_mm", "Fy_over_Fz",
               "stick_area_fraction", "newton_iterations", "factorizations", "time_s", "flange_axial_force_N",
               "flange_contact_fraction"};
  for (const SweepPoint& p : points) {
    const RollingFigures& f = p.figures;
    t.rows.push_back({p.slip_angle_deg, p.camber_deg, p.slip, p.rolling_radius_mm, p.deflection_mm, f.Fx_N, f.Fy_N,
                      f.Fz_N, f.aligning_moment_Nmm, f.overturning_moment_Nmm,
                      f.pneumatic_trail_mm.value_or(kNaN), f.Fz_N != 0.0 ? f.Fy_N / f.Fz_N : kNaN,
                      f.stick_area_fraction, static_cast<double>(p.counts.newton_iterations),
                      static_cast<double>(p.counts.factorizations), p.counts.time_s,
                      largest_flange_axial_force_N(f), smallest_flange_contact_fraction(f)});
  }
  return t;
}

toml::array points_summary(const std::vector<SweepPoint>& points, double mu) {
  toml::array a;
  for (const SweepPoint& p : points) {
    toml::table pt;
    pt.insert("slip", p.slip);
    pt.insert("rolling_radius_mm", p.rolling_radius_mm);
    pt.insert("deflection_mm", p.deflection_mm);
    pt.insert("Qz_N", p.figures.Qz_N);
    pt.insert("Qy_N", p.figures.Qy_N);
    pt.insert("Mx_Nmm", p.figures.Mx_Nmm);
    pt.insert("stick_area_fraction", p.figures.stick_area_fraction);
    insert_tyre_figures(pt, p.figures, p.slip_angle_deg, p.camber_deg, mu);
    pt.insert("newton_iterations", p.counts.newton_iterations);
    pt.insert("time_s", p.counts.time_s);
    if (p.mirrored) pt.insert("mirrored", true);  // the mirror image of the point at −α, not solved
    a.push_back(std::move(pt));
  }
  return a;
}

}  // namespace

void insert_tyre_figures(toml::table& t, const RollingFigures& f, double slip_angle_deg, double camber_deg,
                         double mu) {
  t.insert("slip_angle_deg", slip_angle_deg);
  t.insert("camber_deg", camber_deg);
  t.insert("mu", mu);
  t.insert("Fx_N", f.Fx_N);
  t.insert("Fy_N", f.Fy_N);
  t.insert("Fz_N", f.Fz_N);
  t.insert("Mz_Nmm", f.aligning_moment_Nmm);
  t.insert("overturning_moment_Nmm", f.overturning_moment_Nmm);
  t.insert("rolling_resistance_moment_Nmm", f.rolling_moment_Nmm);
  if (f.pneumatic_trail_mm) t.insert("pneumatic_trail_mm", *f.pneumatic_trail_mm);
  toml::array cp;
  cp.push_back(f.centre_of_pressure_mm.x());
  cp.push_back(f.centre_of_pressure_mm.y());
  t.insert("centre_of_pressure_mm", std::move(cp));
  insert_rim_flanges(t, f);
}

CsvTable angle_sweep_table(const RollingResult& r) { return points_table(r, r.angle_sweep, "slip-angle sweep"); }
CsvTable combined_slip_table(const RollingResult& r) { return points_table(r, r.combined, "combined-slip grid"); }

Plot lateral_force_plot(const RollingResult& r) {
  Plot plot{fmt::format("{}: lateral force against slip angle ({}, μ = {:g})", r.name, support_label(r.support),
                        r.friction),
            "slip angle α [deg]", "lateral force Fy [N] (W-axis: to the left)", {}};
  PlotSeries curve{"Fy", {}, {}, "linespoints pt 7"};
  PlotSeries limits{"±μ Fz", {}, {}, "lines dt 2 lc rgb '#808080'"};
  for (const SweepPoint& p : r.angle_sweep) curve.x.push_back(p.slip_angle_deg), curve.y.push_back(p.figures.Fy_N);
  for (double sign : {1.0, -1.0}) {
    if (sign < 0) limits.x.push_back(kNaN), limits.y.push_back(kNaN);
    for (const SweepPoint& p : r.angle_sweep)
      limits.x.push_back(p.slip_angle_deg), limits.y.push_back(sign * r.friction * p.figures.Fz_N);
  }
  plot.series = {std::move(curve), std::move(limits)};
  return plot;
}

Plot aligning_moment_plot(const RollingResult& r) {
  Plot plot{fmt::format("{}: aligning moment against slip angle ({}, μ = {:g})", r.name, support_label(r.support),
                        r.friction),
            "slip angle α [deg]", "aligning moment Mz [N·m]", {}};
  PlotSeries curve{"Mz", {}, {}, "linespoints pt 7"};
  for (const SweepPoint& p : r.angle_sweep)
    curve.x.push_back(p.slip_angle_deg), curve.y.push_back(1e-3 * p.figures.aligning_moment_Nmm);
  plot.series = {std::move(curve)};
  return plot;
}

Plot friction_ellipse_plot(const RollingResult& r) {
  Plot plot{fmt::format("{}: combined slip, lateral against longitudinal force (μ = {:g})", r.name, r.friction),
            "longitudinal force Fx [N]", "lateral force Fy [N]", {}};
  std::map<double, PlotSeries> lines;
  double fz = 0.0;
  for (const SweepPoint& p : r.combined) {
    PlotSeries& s = lines[p.slip];
    if (s.title.empty()) s = PlotSeries{fmt::format("κ = {:g}", p.slip), {}, {}, "linespoints pt 7"};
    s.x.push_back(p.figures.Fx_N);
    s.y.push_back(p.figures.Fy_N);
    fz += p.figures.Fz_N;
  }
  if (!r.combined.empty()) fz /= static_cast<double>(r.combined.size());
  for (auto& [k, s] : lines) plot.series.push_back(std::move(s));
  PlotSeries circle{"μ Fz", {}, {}, "lines dt 2 lc rgb '#808080'"};
  for (int i = 0; i <= 72; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 72.0;
    circle.x.push_back(r.friction * fz * std::cos(a));
    circle.y.push_back(r.friction * fz * std::sin(a));
  }
  plot.series.push_back(std::move(circle));
  return plot;
}

void insert_cornering_summary(toml::table& t, const RollingResult& r) {
  t.insert("tread_shear", r.planar_shear ? "planar" : "longitudinal");
  if (r.cornering_stiffness_N_per_deg) {
    t.insert("cornering_stiffness_N_per_deg", *r.cornering_stiffness_N_per_deg);
    t.insert("cornering_stiffness_N_per_rad", *r.cornering_stiffness_N_per_deg * 180.0 / std::numbers::pi);
  }
  if (r.pneumatic_trail_at_zero_mm) t.insert("pneumatic_trail_at_zero_mm", *r.pneumatic_trail_at_zero_mm);
  if (r.cornering_stiffness_over_Fz_per_deg)
    t.insert("cornering_stiffness_over_Fz_per_deg", *r.cornering_stiffness_over_Fz_per_deg);
  if (r.pneumatic_trail_over_patch_length)
    t.insert("pneumatic_trail_over_patch_length", *r.pneumatic_trail_over_patch_length);
  if (!r.angle_sweep.empty()) t.insert("angle_sweep", points_summary(r.angle_sweep, r.friction));
  if (!r.combined.empty()) t.insert("combined", points_summary(r.combined, r.friction));
}

}  // namespace tirefem
