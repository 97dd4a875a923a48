#include "tirefem/report/inflation_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "tirefem/analysis/tyre_shell_forms.hpp"

namespace tirefem {
namespace {

Eigen::Vector3d pair_displacement(const Eigen::VectorXd& u, int pair, bool outer) {
  return u.segment<3>(6 * pair + (outer ? 3 : 0));
}

// Circumferential element row whose centre is nearest φ = 0.
int row_nearest_patch_centre(const ShellMesh& m) {
  int best = 0;
  double best_dist = std::numeric_limits<double>::max();
  for (int j = 0; j < m.v_elements(); ++j) {
    const double centre = 0.5 * (m.v_values[j] + m.v_values[j + 1]);
    if (std::abs(centre) < best_dist) {
      best_dist = std::abs(centre);
      best = j;
    }
  }
  return best;
}

int column(const CsvTable& t, const std::string& name) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  return it == t.columns.end() ? -1 : static_cast<int>(it - t.columns.begin());
}

std::vector<double> column_values(const CsvTable& t, int c) {
  std::vector<double> v;
  for (const auto& row : t.rows) v.push_back(row[c]);
  return v;
}

}  // namespace

InflationSummary summarize_inflation(const TyreMesh& tm, const Eigen::VectorXd& u,
                                     const std::vector<ElementResult>& elements) {
  InflationSummary s;
  const ShellMesh& m = tm.mesh;
  // Equator: s = 0 (column 0 in the half model, the middle column in the full model).
  const int i_equator = tm.half_model ? 0 : m.u_nodes() / 2;
  double growth = 0.0;
  for (int j = 0; j < m.v_nodes(); ++j) {
    const int p = m.pair_index(i_equator, j);
    growth += cylindrical_displacement(pair_displacement(u, p, true), m.v_values[j]).radial;
  }
  s.crown_radius_growth_mm = growth / m.v_nodes();
  // Section width of the carcass: extreme lateral positions in the row at φ = 0.
  double max_x0 = -1e300, max_x1 = -1e300, min_x0 = 1e300, min_x1 = 1e300;
  for (int i = 0; i < m.u_nodes(); ++i) {
    const int p = m.pair_index(i, 0);
    const double x0 = m.inner_nodes[p].x(), x1 = x0 + u[6 * p];
    max_x0 = std::max(max_x0, x0), max_x1 = std::max(max_x1, x1);
    min_x0 = std::min(min_x0, x0), min_x1 = std::min(min_x1, x1);
  }
  s.section_width_growth_mm = tm.half_model ? 2.0 * (max_x1 - max_x0) : (max_x1 - min_x1) - (max_x0 - min_x0);
  for (const ElementResult& e : elements) {
    for (size_t k = 0; k < e.inner_cords.force_N.size(); ++k) {
      s.max_carcass_cord_force_N = std::max(s.max_carcass_cord_force_N, e.inner_cords.force_N[k]);
      s.max_carcass_cord_strain = std::max(s.max_carcass_cord_strain, e.inner_cords.strain[k]);
    }
    for (size_t k = 0; k < e.outer_cords.force_N.size(); ++k) {
      s.max_belt_cord_force_N = std::max(s.max_belt_cord_force_N, e.outer_cords.force_N[k]);
      s.max_belt_cord_strain = std::max(s.max_belt_cord_strain, e.outer_cords.strain[k]);
    }
  }
  if (const std::unique_ptr<RimFlangeForm> flange = make_rim_flange_form(tm)) s.rim_flanges = flange->loads(u);
  return s;
}

CsvTable meridian_table(const TyreMesh& tm, const TyreDescription& tyre, const Eigen::VectorXd& u,
                        const std::vector<ElementResult>& elements) {
  const ShellMesh& m = tm.mesh;
  const int j = row_nearest_patch_centre(m);
  const double phi = 0.5 * (m.v_values[j] + m.v_values[j + 1]);
  CsvTable t;
  t.comments = {"tirefem: distributions along the meridian at element centres",
                fmt::format("circumferential row {} (phi = {:.4f} rad); s from the equator", j, phi),
                "face resultants N in the local frame: 1 = meridional, 2 = circumferential (N/mm)",
                "cord strain: engineering strain along the cords; cord force: tension per cord (N)"};
  t.columns = {"s_mm", "x_mm", "r_mm", "zone",
               "carcass_u_lateral_mm", "carcass_u_radial_mm", "breaker_u_lateral_mm", "breaker_u_radial_mm",
               "carcass_N11_N_per_mm", "carcass_N22_N_per_mm", "carcass_N12_N_per_mm",
               "breaker_N11_N_per_mm", "breaker_N22_N_per_mm", "breaker_N12_N_per_mm",
               "interlayer_gamma13", "interlayer_gamma23", "interlayer_tau13_MPa", "interlayer_tau23_MPa",
               "interlayer_E33"};
  // One strain and one force column per named ply (zones may differ in their plies: empty = NaN).
  std::vector<std::string> inner_plies, outer_plies;
  for (const Zone& z : tyre.zones) {
    for (const Ply& p : z.inner.plies)
      if (std::find(inner_plies.begin(), inner_plies.end(), p.name) == inner_plies.end())
        inner_plies.push_back(p.name);
    for (const Ply& p : z.outer.plies)
      if (std::find(outer_plies.begin(), outer_plies.end(), p.name) == outer_plies.end())
        outer_plies.push_back(p.name);
  }
  for (const auto& n : inner_plies) {
    t.columns.push_back("carcass_" + n + "_cord_strain");
    t.columns.push_back("carcass_" + n + "_cord_force_N");
  }
  for (const auto& n : outer_plies) {
    t.columns.push_back("breaker_" + n + "_cord_strain");
    t.columns.push_back("breaker_" + n + "_cord_force_N");
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < m.u_elements(); ++i) {
    const int e = m.element_index(i, j);
    const ElementResult& r = elements[e];
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(), ui = Eigen::Vector3d::Zero(), uo = Eigen::Vector3d::Zero();
    for (int a = 0; a < 4; ++a) {
      const int p = m.elements[e][a];
      centre += 0.25 * m.inner_nodes[p];
      ui += 0.25 * pair_displacement(u, p, false);
      uo += 0.25 * pair_displacement(u, p, true);
    }
    const Eigen::Vector2d x_r(centre.x(), std::hypot(centre.y(), tm.axis_z - centre.z()));
    const auto ci = cylindrical_displacement(ui, phi), co = cylindrical_displacement(uo, phi);
    std::vector<double> row = {tm.element_s[e], x_r[0], x_r[1], static_cast<double>(tm.element_zone[e]),
                               ci.lateral, ci.radial, co.lateral, co.radial,
                               r.state.inner_resultant[0], r.state.inner_resultant[1], r.state.inner_resultant[2],
                               r.state.outer_resultant[0], r.state.outer_resultant[1], r.state.outer_resultant[2],
                               r.state.core_shear[0], r.state.core_shear[1], r.core_shear_stress[0],
                               r.core_shear_stress[1], r.state.core_normal_strain};
    const Zone& zone = tyre.zones[tm.element_zone[e]];
    auto add_plies = [&](const std::vector<std::string>& names, const FaceLayup& face, const FaceCordResults& c) {
      for (const auto& n : names) {
        double strain = nan, force = nan;
        for (size_t k = 0; k < face.plies.size(); ++k)
          if (face.plies[k].name == n) strain = c.strain[k], force = c.force_N[k];
        row.push_back(strain);
        row.push_back(force);
      }
    };
    add_plies(inner_plies, zone.inner, r.inner_cords);
    add_plies(outer_plies, zone.outer, r.outer_cords);
    t.rows.push_back(std::move(row));
  }
  return t;
}

VtuMesh shell_vtu(const TyreMesh& tm, const TyreDescription& tyre, const Eigen::VectorXd& u,
                  const std::vector<ElementResult>& elements) {
  const ShellMesh& m = tm.mesh;
  const int np = m.pair_count();
  VtuMesh v;
  std::vector<Eigen::Vector3d> disp;
  for (int face = 0; face < 2; ++face)
    for (int p = 0; p < np; ++p) {
      v.points.push_back(face == 0 ? m.inner_nodes[p] : m.outer_nodes[p]);
      disp.push_back(pair_displacement(u, p, face == 1));
    }
  std::vector<double> face_id, zone, n11, n22, n12, cord_force, cord_strain, tau13, tau23;
  for (int face = 0; face < 2; ++face)
    for (int e = 0; e < m.element_count(); ++e) {
      const auto& q = m.elements[e];
      const int off = face * np;
      v.quads.push_back({q[0] + off, q[1] + off, q[2] + off, q[3] + off});
      const ElementResult& r = elements[e];
      const Eigen::Vector3d& n = face == 0 ? r.state.inner_resultant : r.state.outer_resultant;
      const FaceCordResults& c = face == 0 ? r.inner_cords : r.outer_cords;
      face_id.push_back(face);
      zone.push_back(tm.element_zone[e]);
      n11.push_back(n[0]);
      n22.push_back(n[1]);
      n12.push_back(n[2]);
      cord_force.push_back(c.force_N.empty() ? 0.0 : *std::max_element(c.force_N.begin(), c.force_N.end()));
      cord_strain.push_back(c.strain.empty() ? 0.0 : *std::max_element(c.strain.begin(), c.strain.end()));
      tau13.push_back(r.core_shear_stress[0]);
      tau23.push_back(r.core_shear_stress[1]);
    }
  (void)tyre;
  v.point_vectors = {{"displacement_mm", disp}};
  v.cell_scalars = {{"N11_meridional_N_per_mm", n11}, {"N22_circumferential_N_per_mm", n22},
                    {"N12_N_per_mm", n12}, {"max_cord_force_N", cord_force},
                    {"max_cord_strain", cord_strain}, {"interlayer_tau13_MPa", tau13},
                    {"interlayer_tau23_MPa", tau23}, {"face_0carcass_1breaker", face_id}, {"zone", zone}};
  return v;
}

std::vector<std::pair<std::string, Plot>> meridian_plots(const CsvTable& t, const TyreMesh& tm,
                                                         const Eigen::VectorXd& u) {
  std::vector<std::pair<std::string, Plot>> plots;
  const std::vector<double> s = column_values(t, column(t, "s_mm"));
  Plot cords{"Cord tension along the meridian", "s from the equator (mm)", "tension per cord (N)", {}};
  for (size_t c = 0; c < t.columns.size(); ++c) {
    const std::string& name = t.columns[c];
    if (name.size() > 12 && name.ends_with("_cord_force_N"))
      cords.series.push_back({name.substr(0, name.size() - 13), s, column_values(t, static_cast<int>(c))});
  }
  plots.emplace_back("cord_tension", cords);
  Plot resultants{"Face stress resultants along the meridian", "s from the equator (mm)",
                  "N (N/mm)", {}};
  for (const char* name : {"carcass_N11_N_per_mm", "carcass_N22_N_per_mm", "breaker_N11_N_per_mm",
                           "breaker_N22_N_per_mm"})
    resultants.series.push_back({name, s, column_values(t, column(t, name))});
  plots.emplace_back("face_resultants", resultants);
  // Cross-section of the carcass line before and after (displacements to scale).
  Plot section{"Carcass cross-section at phi = 0", "x (mm)", "r (mm)", {}};
  PlotSeries before{"undeformed", {}, {}, "lines"}, after{"inflated", {}, {}, "lines"};
  const ShellMesh& m = tm.mesh;
  for (int i = 0; i < m.u_nodes(); ++i) {
    const int p = m.pair_index(i, 0);
    const double phi = m.v_values[0];
    const Eigen::Vector3d x = m.inner_nodes[p];
    const double r0 = std::hypot(x.y(), tm.axis_z - x.z());
    const auto d = cylindrical_displacement(pair_displacement(u, p, false), phi);
    before.x.push_back(x.x()), before.y.push_back(r0);
    after.x.push_back(x.x() + d.lateral), after.y.push_back(r0 + d.radial);
  }
  section.series = {before, after};
  plots.emplace_back("cross_section", section);
  return plots;
}

}  // namespace tirefem
