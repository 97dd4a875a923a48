#include "tirefem/report/footprint_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tirefem/road/support_surface.hpp"

// The load points of a static contact result: the load-curve table, the load characteristic (Fig. 3) and
// the summaries, with the deflections measured from the study's origin (deflection_from).
namespace tirefem {
namespace {

const char* iteration_name(ContactSettings::Iteration it) {
  return it == ContactSettings::Iteration::two_level ? "two_level" : "single_loop";
}

std::string support_description(const SupportDescription& s) {
  switch (s.kind) {
    case SupportDescription::Kind::plane:
      return "road plane";
    case SupportDescription::Kind::drum:
      return fmt::format("test drum, diameter {:g} mm", s.drum_diameter);
    case SupportDescription::Kind::surface: {
      std::string f;
      for (const auto& t : s.terms)
        f += fmt::format("{}{:g} x^{} y^{}", f.empty() ? "" : " + ", t.coefficient, t.x_power, t.y_power);
      return "road surface z = " + (f.empty() ? std::string("0") : f) + " (mm)";
    }
  }
  return "?";
}

bool from_first_touch(const StaticContactResult& r) {
  return r.deflection_from == DeflectionOrigin::first_touch;
}

void insert_study(toml::table& t, const StaticContactResult& r) {
  t.insert("name", r.name);
  t.insert("support", support_kind_name(r.support.kind));
  if (r.support.kind == SupportDescription::Kind::drum) t.insert("drum_diameter_mm", r.support.drum_diameter);
  t.insert("theory", theory_label(r.kinematics));
  t.insert("iteration", iteration_name(r.iteration));
  t.insert("completed", r.completed);
  if (!r.completed) t.insert("failure", r.failure);
  t.insert("first_touch_deflection_mm", r.first_touch_deflection_mm);
  t.insert("deflection_from", from_first_touch(r) ? "first_touch" : "undeformed");
}

// deflection_mm from the study's origin; from the first touch, also deflection_from_undeformed_mm.
void insert_patch(toml::table& t, const StaticContactResult& r, const LoadPoint& p) {
  t.insert("deflection_mm", deflection_from_origin(r, p.deflection_mm));
  if (from_first_touch(r)) t.insert("deflection_from_undeformed_mm", p.deflection_mm);
  t.insert("Qz_N", p.patch.Qz_N);
  t.insert("contact_area_mm2", p.patch.contact_area_mm2);
  t.insert("patch_length_mm", p.patch.patch_length_mm);
  t.insert("patch_width_mm", p.patch.patch_width_mm);
  t.insert("max_pressure_MPa", p.patch.max_pressure_MPa);
  t.insert("mean_pressure_MPa", p.patch.mean_pressure_MPa);
}

}  // namespace

std::string theory_label(Kinematics kinematics) {
  return kinematics == Kinematics::linear ? "linear" : "nonlinear";
}

CsvTable load_curve_table(const StaticContactResult& r) {
  CsvTable t;
  t.comments = {
      r.target_Qz_N ? fmt::format("tirefem: footprint '{}' at Qz = {:g} N (the deflections tried on the way)",
                                  r.name, *r.target_Qz_N)
      : r.given_deflection_mm
          ? fmt::format("tirefem: footprint '{}' at deflection {:g} mm (the load points on the way)", r.name,
                        *r.given_deflection_mm)
          : fmt::format("tirefem: load curve '{}'", r.name),
      "support: " + support_description(r.support),
      fmt::format("theory: {}; contact iteration: {}", theory_label(r.kinematics),
                  iteration_name(r.iteration)),
      r.completed ? std::string("completed")
                  : "stopped early" + (r.failure.empty() ? std::string() : ": " + r.failure),
      "Qz and the patch figures are of the full tyre; pressure = contact pressure qn of the tread",
      "contact_iterations: outer iterations of the last increment; newton_iterations, factorizations, "
      "increments, time_s: all increments to the point",
      "tangent_shift: relative diagonal shift that made the tangent positive definite (0: a stable "
      "equilibrium; above 1e-6: unstable, the tangent is indefinite)"};
  t.columns = {"deflection_mm",     "Qz_N",
               "contact_area_mm2",  "patch_length_mm",
               "patch_width_mm",    "max_pressure_MPa",
               "mean_pressure_MPa", "contact_iterations",
               "newton_iterations", "factorizations",
               "increments",        "time_s",
               "tangent_shift"};
  for (const LoadPoint& p : r.points)
    t.rows.push_back({deflection_from_origin(r, p.deflection_mm), p.patch.Qz_N, p.patch.contact_area_mm2,
                      p.patch.patch_length_mm, p.patch.patch_width_mm, p.patch.max_pressure_MPa,
                      p.patch.mean_pressure_MPa, static_cast<double>(p.contact_iterations),
                      static_cast<double>(p.newton_iterations), static_cast<double>(p.factorizations),
                      static_cast<double>(p.increments), p.time_s, p.tangent_shift});
  if (from_first_touch(r)) {
    // The deflection from the undeformed tyre (the paper's δz) goes second.
    t.comments.push_back(fmt::format("deflection_mm: from the inflated tyre's first touch of the support, at "
                                     "δz = {:.4f} mm from the undeformed tyre; deflection_from_undeformed_mm: δz",
                                     r.first_touch_deflection_mm));
    t.columns.insert(t.columns.begin() + 1, "deflection_from_undeformed_mm");
    for (std::size_t k = 0; k < r.points.size(); ++k)
      t.rows[k].insert(t.rows[k].begin() + 1, r.points[k].deflection_mm);
  } else {
    t.comments.push_back(fmt::format("deflection_mm: from the undeformed tyre; the inflated tyre first touches "
                                     "the support at {:.4f} mm",
                                     r.first_touch_deflection_mm));
  }
  return t;
}

Plot load_characteristic_plot(const std::vector<const StaticContactResult*>& curves) {
  Plot plot{"Load characteristic", "deflection δz [mm]", "vertical load Qz [N]", {}};
  std::vector<std::string> titles;
  for (const StaticContactResult* r : curves)
    if (r)
      titles.push_back(support_label(r->support) + ", " + theory_label(r->kinematics) +
                       (from_first_touch(*r) ? ", from first touch" : ""));
  std::size_t k = 0;
  for (const StaticContactResult* r : curves) {
    if (!r) continue;
    PlotSeries s;
    s.title = titles[k];
    if (std::count(titles.begin(), titles.end(), titles[k]) > 1) s.title += " (" + r->name + ")";
    for (const LoadPoint& p : r->points)
      s.x.push_back(deflection_from_origin(*r, p.deflection_mm)), s.y.push_back(p.patch.Qz_N);
    plot.series.push_back(std::move(s));
    ++k;
  }
  return plot;
}

toml::table load_curve_summary(const StaticContactResult& r) {
  toml::table t;
  insert_study(t, r);
  toml::array points, unstable, passed;
  for (const LoadPoint& p : r.points) {
    toml::table pt;
    insert_patch(pt, r, p);
    pt.insert("contact_iterations", p.contact_iterations);
    pt.insert("newton_iterations", p.newton_iterations);
    pt.insert("tangent_shift", p.tangent_shift);
    pt.insert("stable", stable(p.tangent_shift));
    if (!stable(p.tangent_shift)) unstable.push_back(deflection_from_origin(r, p.deflection_mm));
    if (p.escapes > 0) {
      pt.insert("unstable_equilibria_left", p.escapes);
      passed.push_back(toml::table{{"deflection_mm", deflection_from_origin(r, p.deflection_mm)}, {"tangent_shift", p.escaped_shift}});
    }
    points.push_back(std::move(pt));
  }
  t.insert("points", std::move(points));
  // Where the path passed unstable equilibria (an indefinite converged tangent): the deflections.
  t.insert("unstable_points_deflection_mm", std::move(unstable));
  // Where Newton left an unstable equilibrium for a stable state (equilibrium = "stable").
  t.insert("instabilities_passed", std::move(passed));
  return t;
}

toml::table footprint_summary(const StaticContactResult& r) {
  toml::table t;
  insert_study(t, r);
  if (r.target_Qz_N) t.insert("target_Qz_N", *r.target_Qz_N);
  if (r.given_deflection_mm) t.insert("given_deflection_mm", *r.given_deflection_mm);
  if (!r.points.empty()) insert_patch(t, r, r.points.back());
  return t;
}

}  // namespace tirefem
