#include "tirefem/report/rolling_report.hpp"

#include <fmt/format.h>

#include <limits>
#include <numbers>
#include <stdexcept>

#include "tirefem/report/cornering_report.hpp"
#include "tirefem/report/rim_flange_report.hpp"
#include "tirefem/report/tread_point_grid.hpp"
#include "tirefem/road/support_surface.hpp"

namespace tirefem {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

double or_nan(const std::optional<double>& v) { return v ? *v : kNaN; }

std::string optional_text(const std::optional<double>& v, const char* unit) {
  return v ? fmt::format("{:g}{}", *v, unit) : std::string("not found");
}

const char* travel_name(bool reverse) { return reverse ? "-y" : "+y"; }

// "'brake 5%' (given_slip, kappa = -0.05, Rk = 290.1 mm)"; "'spin' (full_slip, spinning, Rk = 0 mm)"
std::string state_label(const RollingStateResult& s) {
  std::string text = fmt::format("'{}' ({}", s.name, rolling_state_kind_name(s.spec.kind));
  if (s.spec.kind == RollingStateSpec::Kind::full_slip) text += s.spec.braking ? ", locked" : ", spinning";
  if (s.slip) text += fmt::format(", κ = {:.4g}", *s.slip);
  if (s.rolling_radius_mm) text += fmt::format(", Rk = {:.2f} mm", *s.rolling_radius_mm);
  return text + ")";
}

void check_state(const RollingResult& r, const RollingStateResult& s) {
  const std::size_t n = r.tread_points.size();
  if (n == 0) throw std::invalid_argument(fmt::format("rolling result '{}': no tread points", r.name));
  if (s.normal.size() != n || s.tangential.size() != n)
    throw std::invalid_argument(fmt::format(
        "rolling result '{}', state '{}': {} normal and {} tangential tread point states for {} tread points",
        r.name, s.name, s.normal.size(), s.tangential.size(), n));
}

// The grid of a state's tread points (tread_point_grid.hpp) and its patch window: the points with qn > 0
// (without contact: those of largest penetration) plus kPatchMarginPoints rows / columns.
struct StateGrid {
  TreadGrid grid;
  TreadWindow window;
};

StateGrid state_grid(const RollingResult& r, const RollingStateResult& s) {
  check_state(r, s);
  TreadGrid g = tread_grid(r.tread_points, r.half_model);
  const TreadWindow w = patch_window(g, s.normal, kPatchMarginPoints);
  return {std::move(g), w};
}

double qy(const RollingResult& r, const RollingStateResult& s, int n) {
  const double weight = r.tread_points[n].weight;
  return weight > 0 ? s.tangential[n].force.y() / weight : 0.0;
}

double status_code(TreadContact c) {
  return c == TreadContact::stick ? 1.0 : c == TreadContact::slip ? 2.0 : 0.0;
}

std::string standing_comment(const RollingResult& r) {
  if (!r.standing_stiffness) return "standing stiffness: not measured (a flat-plate test: on a plane only)";
  const StandingStiffness& c = *r.standing_stiffness;
  return fmt::format("standing tyre, tread glued to the plane: longitudinal stiffness Cx = {:g} N/mm{}; relaxation "
                     "length Kxkappa/Cx = {}{}",
                     c.longitudinal_N_per_mm,
                     c.lateral_N_per_mm ? fmt::format(", lateral Cy = {:g} N/mm", *c.lateral_N_per_mm) : "",
                     optional_text(r.longitudinal_relaxation_length_mm, " mm"),
                     r.lateral_relaxation_length_mm
                         ? fmt::format(", Kyalpha/Cy = {:g} mm", *r.lateral_relaxation_length_mm) : "");
}

std::vector<std::string> study_comments(const RollingResult& r) {
  return {
      fmt::format("support: {}; friction mu = {:g}; travel {} (the support moves in {} under the tyre)",
                  support_label(r.support), r.friction, travel_name(r.reverse), travel_name(!r.reverse)),
      fmt::format("deflection {:g} mm; loaded radius Rd = {:g} mm; effective rolling radius Re = {}; "
                  "slip stiffness dQy/dkappa = {}",
                  r.deflection_mm, r.loaded_radius_mm, optional_text(r.effective_rolling_radius_mm, " mm"),
                  optional_text(r.slip_stiffness_N, " N")),
      standing_comment(r),
      "slip kappa = Re/Rk - 1 (Rk = V/Omega the rolling radius); Qy along the travel (> 0 traction); Mx "
      "about the axle"};
}

void insert_figures(toml::table& t, const RollingFigures& f) {
  t.insert("Qz_N", f.Qz_N);
  t.insert("Qy_N", f.Qy_N);
  t.insert("Mx_Nmm", f.Mx_Nmm);
  t.insert("stick_area_fraction", f.stick_area_fraction);
}

}  // namespace

std::string rolling_state_kind_name(RollingStateSpec::Kind kind) {
  switch (kind) {
    case RollingStateSpec::Kind::free:
      return "free";
    case RollingStateSpec::Kind::given_slip:
      return "given_slip";
    case RollingStateSpec::Kind::given_radius:
      return "given_radius";
    case RollingStateSpec::Kind::full_stick:
      return "full_stick";
    case RollingStateSpec::Kind::full_slip:
      return "full_slip";
  }
  return "?";
}

CsvTable rolling_states_table(const RollingResult& r) {
  CsvTable t;
  t.comments = {fmt::format("tirefem: rolling states of '{}'", r.name)};
  for (const std::string& c : study_comments(r)) t.comments.push_back(c);
  t.comments.push_back(r.completed
                           ? std::string("completed")
                           : "stopped early" + (r.failure.empty() ? std::string() : ": " + r.failure));
  t.comments.push_back(
      "state: 0 free, 1 given_slip, 2 given_radius, 3 full_stick, 4 full_slip; nan: not defined (slip of a "
      "spinning wheel, Rk of a locked one) or not converged (the figures)");
  t.comments.push_back(
      "Fx Fy Fz Mz overturning_moment: W-axis system (ISO 8855 / TYDEX) at the contact centre (X along the "
      "travel, Y to the left, Z up); pneumatic_trail = -Mz/Fy (nan where |Fy| <= 1e-3 Fz)");
  t.columns = {"state", "slip", "rolling_radius_mm", "loaded_radius_mm", "Qz_N", "Qy_N", "Mx_Nmm",
               "stick_area_fraction", "contact_area_mm2", "max_traction_MPa", "contact_iterations",
               "newton_iterations", "factorizations", "solves", "time_s", "converged", "slip_angle_deg",
               "camber_deg", "Fx_N", "Fy_N", "Fz_N", "Mz_Nmm", "overturning_moment_Nmm", "pneumatic_trail_mm",
               "flange_axial_force_N", "flange_contact_fraction"};
  for (std::size_t k = 0; k < r.states.size(); ++k) {
    const RollingStateResult& s = r.states[k];
    t.comments.push_back(
        fmt::format("row {}: {}{}", k + 1, state_label(s),
                    s.converged ? "" : ": not converged" + (s.failure.empty() ? "" : ", " + s.failure)));
    const RollingFigures& f = s.figures;
    const auto figure = [&](double v) { return s.converged ? v : kNaN; };
    const RollingSolveCounts& c = s.counts;
    const double loaded_radius = loaded_radius_at(r, s.deflection_mm.value_or(r.deflection_mm));
    t.rows.push_back({static_cast<double>(s.spec.kind), or_nan(s.slip), or_nan(s.rolling_radius_mm),
                      loaded_radius, figure(f.Qz_N), figure(f.Qy_N), figure(f.Mx_Nmm),
                      figure(f.stick_area_fraction), figure(f.contact_area_mm2), figure(f.max_traction_MPa),
                      static_cast<double>(c.contact_iterations), static_cast<double>(c.newton_iterations),
                      static_cast<double>(c.factorizations), static_cast<double>(c.solves), c.time_s,
                      s.converged ? 1.0 : 0.0, s.spec.slip_angle_deg, s.spec.camber_deg, figure(f.Fx_N),
                      figure(f.Fy_N), figure(f.Fz_N), figure(f.aligning_moment_Nmm),
                      figure(f.overturning_moment_Nmm), s.converged ? or_nan(f.pneumatic_trail_mm) : kNaN,
                      figure(largest_flange_axial_force_N(f)), figure(smallest_flange_contact_fraction(f))});
  }
  return t;
}

CsvTable slip_sweep_table(const RollingResult& r) {
  CsvTable t;
  t.comments = {
      fmt::format("tirefem: longitudinal force-slip sweep of '{}' (converged points, by slip)", r.name)};
  for (const std::string& c : study_comments(r)) t.comments.push_back(c);
  t.columns = {"slip", "rolling_radius_mm", "deflection_mm", "Qz_N", "Qy_N", "Mx_Nmm", "Qy_over_Qz",
               "stick_area_fraction", "contact_iterations", "newton_iterations", "factorizations", "time_s",
               "flange_axial_force_N", "flange_contact_fraction"};
  for (const SweepPoint& p : r.sweep) {
    const RollingFigures& f = p.figures;
    t.rows.push_back({p.slip, p.rolling_radius_mm, p.deflection_mm, f.Qz_N, f.Qy_N, f.Mx_Nmm,
                      f.Qz_N != 0.0 ? f.Qy_N / f.Qz_N : kNaN, f.stick_area_fraction,
                      static_cast<double>(p.counts.contact_iterations),
                      static_cast<double>(p.counts.newton_iterations),
                      static_cast<double>(p.counts.factorizations), p.counts.time_s,
                      largest_flange_axial_force_N(f), smallest_flange_contact_fraction(f)});
  }
  return t;
}

Plot slip_sweep_plot(const RollingResult& r) {
  Plot plot{fmt::format("{}: longitudinal force against slip ({}, μ = {:g})", r.name,
                        support_label(r.support), r.friction),
            "longitudinal slip κ [-]",
            "longitudinal force Qy [N]",
            {}};
  PlotSeries curve{"Qy", {}, {}, "linespoints pt 7"};
  PlotSeries limits{"±μ Qz", {}, {}, "lines dt 2 lc rgb '#808080'"};
  for (const SweepPoint& p : r.sweep) curve.x.push_back(p.slip), curve.y.push_back(p.figures.Qy_N);
  for (double sign : {1.0, -1.0}) {
    if (sign < 0 && !r.sweep.empty()) limits.x.push_back(kNaN), limits.y.push_back(kNaN);  // a gap
    for (const SweepPoint& p : r.sweep)
      limits.x.push_back(p.slip), limits.y.push_back(sign * r.friction * p.figures.Qz_N);
  }
  plot.series = {std::move(curve), std::move(limits)};
  return plot;
}

CsvTable rolling_tread_table(const RollingResult& r, const RollingStateResult& s) {
  const auto [g, w] = state_grid(r, s);
  CsvTable t;
  t.comments = {
      fmt::format("tirefem: tread points of '{}', state {}", r.name, state_label(s)),
      fmt::format("window: the contact (qn > 0) plus {} rows / columns of tread points; the model's own "
                  "points (a half model is not mirrored)",
                  kPatchMarginPoints),
      fmt::format("s from the equator along the meridian; phi = 0 at the bottom; x y z: current position; "
                  "traction and shear along the support's motion ({}); qy: y component of the tangential "
                  "stress on the tyre",
                  travel_name(!r.reverse)),
      "status: 0 out of contact, 1 stick, 2 slip"};
  t.columns = {"s_mm",         "phi_deg",      "x_mm",   "y_mm",     "z_mm",
               "pressure_MPa", "traction_MPa", "qy_MPa", "shear_mm", "status"};
  for (int j = w.j0; j <= w.j1; ++j)
    for (int i = w.i0; i <= w.i1; ++i) {
      const int n = g.at(i, j);
      if (n < 0 || g.mirrored[i]) continue;
      const Eigen::Vector3d& x = s.normal[n].position;
      const TreadTraction& q = s.tangential[n];
      t.rows.push_back({r.tread_points[n].u, r.tread_points[n].v * kDeg, x.x(), x.y(), x.z(),
                        s.normal[n].pressure, q.traction, qy(r, s, n), q.shear, status_code(q.status)});
    }
  return t;
}

HeatMap traction_map_s_phi(const RollingResult& r, const RollingStateResult& s) {
  const auto [g, w] = state_grid(r, s);
  HeatMap m;
  m.title = fmt::format("{} {}: tangential stress, {}, μ = {:g}", r.name, state_label(s),
                        support_label(r.support), r.friction);
  set_s_phi_axes(m, g, w);
  m.value_label = "tangential stress qy (y component) [MPa]";
  PlotSeries slip{"slip", {}, {}, "points pt 7 ps 0.4 lc rgb '#000000'"};
  for (int j = w.j0; j <= w.j1; ++j) {
    std::vector<double> row;
    for (int i = w.i0; i <= w.i1; ++i) {
      const int n = g.at(i, j);
      row.push_back(n < 0 ? 0.0 : qy(r, s, n));  // y is unchanged by the mirror x → −x
      if (n >= 0 && s.tangential[n].status == TreadContact::slip)
        slip.x.push_back(g.u[i]), slip.y.push_back(g.v[j] * kDeg);
    }
    m.values.push_back(std::move(row));
  }
  m.overlays.push_back(std::move(slip));
  return m;
}

VtuMesh tread_points_vtu(const RollingResult& r, const RollingStateResult& s) {
  check_state(r, s);
  const std::size_t n = r.tread_points.size();
  VtuMesh v;
  std::vector<double> pressure(n), traction(n), q_y(n), shear(n), status(n);
  std::vector<Eigen::Vector3d> traction_vector(n);
  for (std::size_t k = 0; k < n; ++k) {
    v.points.push_back(s.normal[k].position);
    v.vertices.push_back(static_cast<int>(k));
    pressure[k] = s.normal[k].pressure;
    traction[k] = s.tangential[k].traction;
    q_y[k] = qy(r, s, static_cast<int>(k));
    shear[k] = s.tangential[k].shear;
    status[k] = status_code(s.tangential[k].status);
    const double w = r.tread_points[k].weight;
    traction_vector[k] = w > 0 ? Eigen::Vector3d(s.tangential[k].force / w) : Eigen::Vector3d::Zero();
  }
  v.point_vectors = {{"tangential_stress_MPa", std::move(traction_vector)}};
  v.point_scalars = {{"pressure_MPa", std::move(pressure)},
                     {"traction_MPa", std::move(traction)},
                     {"qy_MPa", std::move(q_y)},
                     {"shear_mm", std::move(shear)},
                     {"status", std::move(status)}};
  return v;
}

toml::table rolling_summary(const RollingResult& r) {
  toml::table t;
  t.insert("name", r.name);
  t.insert("support", support_kind_name(r.support.kind));
  if (r.support.kind == SupportDescription::Kind::drum) t.insert("drum_diameter_mm", r.support.drum_diameter);
  t.insert("friction", r.friction);
  t.insert("travel", travel_name(r.reverse));
  t.insert("completed", r.completed);
  if (!r.completed) t.insert("failure", r.failure);
  if (r.footprint.target_Qz_N) t.insert("target_Qz_N", *r.footprint.target_Qz_N);
  t.insert("deflection_mm", r.deflection_mm);
  t.insert("loaded_radius_mm", r.loaded_radius_mm);
  if (r.effective_rolling_radius_mm) t.insert("effective_rolling_radius_mm", *r.effective_rolling_radius_mm);
  if (r.slip_stiffness_N) t.insert("slip_stiffness_N", *r.slip_stiffness_N);
  if (r.standing_stiffness) {
    const StandingStiffness& c = *r.standing_stiffness;
    toml::table st;
    st.insert("longitudinal_N_per_mm", c.longitudinal_N_per_mm);
    if (c.lateral_N_per_mm) st.insert("lateral_N_per_mm", *c.lateral_N_per_mm);
    if (c.yaw_Nmm_per_rad) st.insert("yaw_Nm_per_deg", Nm_per_deg(*c.yaw_Nmm_per_rad));
    st.insert("tread_shear_N_per_mm", c.tread_shear_N_per_mm);
    st.insert("stable", c.stable);
    st.insert("factorizations", c.factorizations);
    st.insert("assembly_time_s", c.assembly_s);
    st.insert("factorization_time_s", c.analysis_s + c.factorization_s);  // with its symbolic analysis
    st.insert("time_s", c.time_s);
    t.insert("standing_stiffness", std::move(st));
  }
  if (r.longitudinal_relaxation_length_mm)
    t.insert("longitudinal_relaxation_length_mm", *r.longitudinal_relaxation_length_mm);
  if (r.lateral_relaxation_length_mm) t.insert("lateral_relaxation_length_mm", *r.lateral_relaxation_length_mm);
  toml::array states;
  for (const RollingStateResult& s : r.states) {
    toml::table st;
    st.insert("name", s.name);
    st.insert("state", rolling_state_kind_name(s.spec.kind));
    if (s.slip) st.insert("slip", *s.slip);
    if (s.rolling_radius_mm) st.insert("rolling_radius_mm", *s.rolling_radius_mm);
    st.insert("loaded_radius_mm", r.loaded_radius_mm);
    if (s.converged) {
      insert_figures(st, s.figures);
      st.insert("contact_area_mm2", s.figures.contact_area_mm2);
      insert_tyre_figures(st, s.figures, s.spec.slip_angle_deg, s.spec.camber_deg, r.friction);
    }
    st.insert("contact_iterations", s.counts.contact_iterations);
    st.insert("newton_iterations", s.counts.newton_iterations);
    st.insert("factorizations", s.counts.factorizations);
    st.insert("time_s", s.counts.time_s);
    st.insert("converged", s.converged);
    if (!s.converged) st.insert("failure", s.failure);
    states.push_back(std::move(st));
  }
  t.insert("states", std::move(states));
  if (!r.sweep.empty()) {
    toml::array sweep;
    for (const SweepPoint& p : r.sweep) {
      toml::table pt;
      pt.insert("slip", p.slip);
      pt.insert("rolling_radius_mm", p.rolling_radius_mm);
      pt.insert("deflection_mm", p.deflection_mm);
      insert_figures(pt, p.figures);
      insert_rim_flanges(pt, p.figures);
      pt.insert("newton_iterations", p.counts.newton_iterations);
      pt.insert("factorizations", p.counts.factorizations);
      pt.insert("time_s", p.counts.time_s);
      sweep.push_back(std::move(pt));
    }
    t.insert("sweep", std::move(sweep));
  }
  insert_cornering_summary(t, r);
  return t;
}

}  // namespace tirefem
