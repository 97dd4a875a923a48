#include "tirefem/report/footprint_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "tirefem/report/inflation_report.hpp"
#include "tirefem/report/tread_point_grid.hpp"
#include "tirefem/road/support_surface.hpp"

namespace tirefem {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The grid of a result's tread points (tread_point_grid.hpp), after checking that the final state has
// one entry per tread point.
TreadGrid tread_grid(const StaticContactResult& r) {
  const auto& pts = r.tread_points;
  if (pts.empty()) throw std::invalid_argument(fmt::format("contact result '{}': no tread points", r.name));
  if (r.final_state.tread.size() != pts.size())
    throw std::invalid_argument(fmt::format("contact result '{}': {} tread point states for {} tread points",
                                            r.name, r.final_state.tread.size(), pts.size()));
  return tirefem::tread_grid(pts, r.half_model);
}

Eigen::Vector3d grid_position(const TreadGrid& g, const std::vector<TreadPointState>& states, int i, int j) {
  Eigen::Vector3d x = states[g.at(i, j)].position;
  if (g.mirrored[i]) x.x() = -x.x();
  return x;
}

// (ξ, η) ∈ [0, 1]² with X = P0 (1−ξ)(1−η) + P1 ξ (1−η) + P2 ξ η + P3 (1−ξ) η, by Newton's method;
// false when X lies outside the quadrilateral (or it is degenerate).
bool inverse_bilinear(const std::array<Eigen::Vector2d, 4>& P, const Eigen::Vector2d& X, double& xi,
                      double& eta) {
  xi = eta = 0.5;
  const double size = (P[2] - P[0]).norm() + (P[3] - P[1]).norm();
  for (int it = 0; it < 30; ++it) {
    const Eigen::Vector2d F =
        P[0] * (1 - xi) * (1 - eta) + P[1] * xi * (1 - eta) + P[2] * xi * eta + P[3] * (1 - xi) * eta - X;
    Eigen::Matrix2d J;
    J.col(0) = (P[1] - P[0]) * (1 - eta) + (P[2] - P[3]) * eta;
    J.col(1) = (P[3] - P[0]) * (1 - xi) + (P[2] - P[1]) * xi;
    const double det = J.determinant();
    if (!(std::abs(det) > 1e-12 * size * size)) return false;
    const Eigen::Vector2d d = J.inverse() * F;
    xi -= d[0], eta -= d[1];
    if (std::abs(xi) > 10 || std::abs(eta) > 10) return false;
    if (d.norm() < 1e-13) break;
  }
  constexpr double tol = 1e-9;
  return xi >= -tol && xi <= 1 + tol && eta >= -tol && eta <= 1 + tol;
}

int column(const CsvTable& t, const std::string& name) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  if (it == t.columns.end()) throw std::invalid_argument("table has no column '" + name + "'");
  return static_cast<int>(it - t.columns.begin());
}

std::vector<double> column_values(const CsvTable& t, int c) {
  std::vector<double> v;
  for (const auto& row : t.rows) v.push_back(row[c]);
  return v;
}

std::string strip_suffix(const std::string& name, const std::string& suffix) {
  return name.ends_with(suffix) ? name.substr(0, name.size() - suffix.size()) : name;
}

}  // namespace

CsvTable tread_points_table(const StaticContactResult& r) {
  const TreadGrid g = tread_grid(r);
  const auto& states = r.final_state.tread;
  const TreadWindow w = patch_window(g, states, kPatchMarginPoints);
  CsvTable t;
  t.comments = {
      fmt::format("tirefem: tread points of '{}' at deflection {:g} mm", r.name, r.final_state.deflection_mm),
      fmt::format("window: the contact (qn > 0) plus {} rows / columns of tread points; the "
                  "model's own points (a half model is not mirrored)",
                  kPatchMarginPoints),
      "s from the equator along the meridian; phi = 0 at the bottom; x y z: current position of "
      "the tread point (tread surface); penetration g > 0 inside the support"};
  t.columns = {"s_mm", "phi_deg", "x_mm", "y_mm", "z_mm", "penetration_mm", "pressure_MPa"};
  for (int j = w.j0; j <= w.j1; ++j)
    for (int i = w.i0; i <= w.i1; ++i) {
      const int n = g.at(i, j);
      if (n < 0 || g.mirrored[i]) continue;
      const TreadPointState& s = states[n];
      t.rows.push_back({r.tread_points[n].u, r.tread_points[n].v * kDeg, s.position.x(), s.position.y(),
                        s.position.z(), s.penetration, s.pressure});
    }
  return t;
}

HeatMap pressure_map_s_phi(const StaticContactResult& r) {
  const TreadGrid g = tread_grid(r);
  const auto& states = r.final_state.tread;
  const TreadWindow w = patch_window(g, states, kPatchMarginPoints);
  HeatMap m;
  m.title = fmt::format("{}: contact pressure at δz = {:.2f} mm ({}, {})", r.name,
                        r.final_state.deflection_mm, support_label(r.support), theory_label(r.kinematics));
  set_s_phi_axes(m, g, w);
  m.value_label = "contact pressure [MPa]";
  for (int j = w.j0; j <= w.j1; ++j) {
    std::vector<double> row;
    for (int i = w.i0; i <= w.i1; ++i) {
      const int n = g.at(i, j);
      row.push_back(n < 0 ? 0.0 : states[n].pressure);
    }
    m.values.push_back(std::move(row));
  }
  return m;
}

HeatMap footprint_map_xy(const StaticContactResult& r, double cell_mm) {
  if (!(cell_mm > 0)) throw std::invalid_argument(fmt::format("footprint map: cell size {} mm", cell_mm));
  const TreadGrid g = tread_grid(r);
  const auto& states = r.final_state.tread;
  // Window: extent of the patch points in (x, y), plus the margin, rounded out to multiples of the cell.
  const std::vector<char> active = patch_points(states);
  double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min, y_min = x_min, y_max = -x_min;
  for (int j = 0; j < g.nv(); ++j)
    for (int i = 0; i < g.nu(); ++i) {
      const int n = g.at(i, j);
      if (n < 0 || !active[n]) continue;
      const Eigen::Vector3d x = grid_position(g, states, i, j);
      x_min = std::min(x_min, x.x()), x_max = std::max(x_max, x.x());
      y_min = std::min(y_min, x.y()), y_max = std::max(y_max, x.y());
    }
  const auto first_node = [&](double lo) { return std::floor((lo - kFootprintMarginMm) / cell_mm); };
  const auto last_node = [&](double hi) { return std::ceil((hi + kFootprintMarginMm) / cell_mm); };
  const double lo_x = first_node(x_min) * cell_mm, lo_y = first_node(y_min) * cell_mm;
  const int nx = static_cast<int>(last_node(x_max) - first_node(x_min)) + 1;
  const int ny = static_cast<int>(last_node(y_max) - first_node(y_min)) + 1;
  HeatMap m;
  m.title = fmt::format("{}: footprint at δz = {:.2f} mm ({}, {})", r.name, r.final_state.deflection_mm,
                        support_label(r.support), theory_label(r.kinematics));
  m.x_label = "x lateral [mm]";
  m.y_label = "y direction of travel [mm]";
  m.value_label = "contact pressure [MPa]";
  m.equal_axes = true;
  for (int k = 0; k < nx; ++k) m.x.push_back(lo_x + k * cell_mm);
  for (int k = 0; k < ny; ++k) m.y.push_back(lo_y + k * cell_mm);
  m.values.assign(ny, std::vector<double>(nx, 0.0));
  std::vector<char> done(static_cast<std::size_t>(nx) * ny, 0);
  const double hi_x = m.x.back(), hi_y = m.y.back();
  for (int j = 0; j + 1 < g.nv(); ++j)
    for (int i = 0; i + 1 < g.nu(); ++i) {
      const std::array<std::array<int, 2>, 4> corners{{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
      std::array<Eigen::Vector2d, 4> P;
      std::array<double, 4> q{};
      bool complete = true, loaded = false;
      for (int a = 0; a < 4; ++a) {
        const int n = g.at(corners[a][0], corners[a][1]);
        if (n < 0) {
          complete = false;
          break;
        }
        P[a] = grid_position(g, states, corners[a][0], corners[a][1]).head<2>();
        q[a] = states[n].pressure;
        loaded = loaded || q[a] != 0.0;
      }
      if (!complete || !loaded) continue;  // nodes of unloaded cells keep their 0
      double bx0 = P[0].x(), bx1 = bx0, by0 = P[0].y(), by1 = by0;
      for (const auto& p : P) {
        bx0 = std::min(bx0, p.x()), bx1 = std::max(bx1, p.x());
        by0 = std::min(by0, p.y()), by1 = std::max(by1, p.y());
      }
      if (bx1 < lo_x || bx0 > hi_x || by1 < lo_y || by0 > hi_y) continue;
      const int kx0 = std::max(0, static_cast<int>(std::ceil((bx0 - lo_x) / cell_mm - 1e-9)));
      const int kx1 = std::min(nx - 1, static_cast<int>(std::floor((bx1 - lo_x) / cell_mm + 1e-9)));
      const int ky0 = std::max(0, static_cast<int>(std::ceil((by0 - lo_y) / cell_mm - 1e-9)));
      const int ky1 = std::min(ny - 1, static_cast<int>(std::floor((by1 - lo_y) / cell_mm + 1e-9)));
      for (int ky = ky0; ky <= ky1; ++ky)
        for (int kx = kx0; kx <= kx1; ++kx) {
          char& d = done[static_cast<std::size_t>(ky) * nx + kx];
          double xi = 0, eta = 0;
          if (d || !inverse_bilinear(P, Eigen::Vector2d(m.x[kx], m.y[ky]), xi, eta)) continue;
          xi = std::clamp(xi, 0.0, 1.0), eta = std::clamp(eta, 0.0, 1.0);
          m.values[ky][kx] =
              q[0] * (1 - xi) * (1 - eta) + q[1] * xi * (1 - eta) + q[2] * xi * eta + q[3] * (1 - xi) * eta;
          d = 1;
        }
    }
  return m;
}

CsvTable circumferential_belt_table(
    const TyreMesh& tm, const TyreDescription& tyre,
    const std::vector<std::pair<std::string, const std::vector<ElementResult>*>>& states) {
  const ShellMesh& m = tm.mesh;
  for (const auto& [name, elements] : states)
    if (!elements || static_cast<int>(elements->size()) != m.element_count())
      throw std::invalid_argument(
          fmt::format("circumferential belt table: state '{}' has {} element results "
                      "for {} elements",
                      name, elements ? elements->size() : 0, m.element_count()));
  // Equatorial column: |s| smallest, a tie (full model: ±s) going to s > 0.
  int col = 0;
  for (int i = 1; i < m.u_elements(); ++i) {
    const double s = tm.element_s[m.element_index(i, 0)], best = tm.element_s[m.element_index(col, 0)];
    const double tol = 1e-9 * (1.0 + std::abs(best));
    if (std::abs(s) < std::abs(best) - tol || (std::abs(std::abs(s) - std::abs(best)) <= tol && s > best))
      col = i;
  }
  const int zone = tm.element_zone[m.element_index(col, 0)];
  const FaceLayup& face = tyre.zones.at(zone).outer;
  std::vector<std::string> plies;
  for (std::size_t k = 0; k < face.plies.size(); ++k) {
    const std::string& n = face.plies[k].name;
    const auto uses =
        std::count_if(face.plies.begin(), face.plies.end(), [&](const Ply& p) { return p.name == n; });
    const auto before = std::count_if(face.plies.begin(), face.plies.begin() + static_cast<long>(k),
                                      [&](const Ply& p) { return p.name == n; });
    plies.push_back(uses > 1 ? fmt::format("{}_{}", n, before + 1) : n);
  }
  CsvTable t;
  t.comments = {
      "tirefem: breaker (outer face) cords along the circumference in the equatorial plane",
      fmt::format("element column {} (s = {:.4f} mm, zone '{}'), values at element centres", col,
                  tm.element_s[m.element_index(col, 0)], tyre.zones[zone].name),
      "per state and ply: force_N = tension per cord (N), strain = engineering strain along the cords"};
  if (plies.empty()) t.comments.push_back("the outer face has no plies in this zone");
  t.columns = {"phi_deg"};
  for (const auto& st : states)
    for (const auto& p : plies) {
      t.columns.push_back(st.first + "_" + p + "_force_N");
      t.columns.push_back(st.first + "_" + p + "_strain");
    }
  for (int j = 0; j < m.v_elements(); ++j) {
    const int e = m.element_index(col, j);
    std::vector<double> row{0.5 * (m.v_values[j] + m.v_values[j + 1]) * kDeg};
    for (const auto& st : states) {
      const FaceCordResults& c = (*st.second)[e].outer_cords;
      for (std::size_t k = 0; k < plies.size(); ++k) {
        row.push_back(k < c.force_N.size() ? c.force_N[k] : kNaN);
        row.push_back(k < c.strain.size() ? c.strain[k] : kNaN);
      }
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

Plot circumferential_belt_plot(const CsvTable& t) {
  Plot plot{"Breaker cord tension along the circumference (equatorial plane)",
            "φ [deg]",
            "tension per cord [N]",
            {}};
  // One colour per state, one dash pattern per ply of the state ("<state>_<ply>_force_N").
  static constexpr const char* kColours[] = {"#000000", "#e69f00", "#56b4e9", "#009e73", "#d55e00",
                                             "#0072b2", "#cc79a7", "#999999", "#f0e442", "#8c564b"};
  const std::vector<double> phi = column_values(t, column(t, "phi_deg"));
  std::vector<std::string> states;
  std::string last_state;
  int ply = 0;
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    if (!t.columns[c].ends_with("_force_N")) continue;
    const std::string label = strip_suffix(t.columns[c], "_force_N");
    const std::string state = label.substr(0, label.rfind('_'));
    ply = state == last_state ? ply + 1 : 0;
    last_state = state;
    if (std::find(states.begin(), states.end(), state) == states.end()) states.push_back(state);
    const std::size_t k = std::find(states.begin(), states.end(), state) - states.begin();
    plot.series.push_back({label, phi, column_values(t, static_cast<int>(c)),
                           fmt::format("lines lw 2 lc rgb '{}' dt {}", kColours[k % std::size(kColours)], 1 + ply)});
  }
  return plot;
}

Plot meridian_cord_strain_plot(const std::vector<std::pair<std::string, const CsvTable*>>& tables) {
  Plot plot{"Cord strain along the meridian under the patch centre",
            "s from the equator [mm]",
            "cord strain (engineering) [-]",
            {}};
  for (const auto& [label, table] : tables) {
    if (!table) continue;
    const std::vector<double> s = column_values(*table, column(*table, "s_mm"));
    for (std::size_t c = 0; c < table->columns.size(); ++c) {
      const std::string& name = table->columns[c];
      if (!name.ends_with("_cord_strain")) continue;
      std::string ply = strip_suffix(name, "_cord_strain");
      if (const auto pos = ply.find('_'); pos != std::string::npos) ply[pos] = ' ';  // "breaker belt1"
      plot.series.push_back({label + ", " + ply, s, column_values(*table, static_cast<int>(c))});
    }
  }
  return plot;
}

VtuMesh support_vtu(const StaticContactResult& r, double half_extent_mm) {
  if (!(half_extent_mm > 0))
    throw std::invalid_argument(fmt::format("support surface: half extent {} mm", half_extent_mm));
  constexpr int n = 61;
  const auto support = make_support(r.support);
  const double deflection = r.final_state.deflection_mm;
  VtuMesh v;
  std::vector<double> height;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -half_extent_mm + 2.0 * half_extent_mm * i / (n - 1);
      const double y = -half_extent_mm + 2.0 * half_extent_mm * j / (n - 1);
      const double z = support->height(x, y, deflection);
      v.points.emplace_back(x, y, z);
      height.push_back(z);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int p = j * n + i;
      v.quads.push_back({p, p + 1, p + 1 + n, p + n});  // counter-clockwise seen from above (the tyre)
    }
  v.point_scalars = {{"height_mm", height}};
  return v;
}

std::vector<double> nodal_contact_pressure(const TyreMesh& tm, const TyreDescription& tyre,
                                           const StaticContactResult& r, const Eigen::VectorXd& u) {
  const ShellMesh& m = tm.mesh;
  if (u.size() != m.dof_count())
    throw std::invalid_argument(
        fmt::format("nodal contact pressure: displacement of size {} for {} DOFs", u.size(), m.dof_count()));
  const auto support = make_support(r.support);
  const double deflection = r.final_state.deflection_mm;
  std::vector<double> q(m.pair_count(), 0.0);
  if (tyre.tread_height.s.empty()) return q;
  for (int p = 0; p < m.pair_count(); ++p) {
    const double s = tm.pair_s(p);
    if (std::abs(s) > tyre.tread_end_s) continue;
    const double hp = tread_height_at(tyre, s);
    if (hp < 0) continue;
    const Eigen::Vector3d normal = (m.outer_nodes[p] - m.inner_nodes[p]).normalized();
    const Eigen::Vector3d x = m.outer_nodes[p] + hp * normal + u.segment<3>(outer_dof(p, 0));
    q[p] = tyre.tread_stiffness * std::max(support->penetration(x, deflection).value, 0.0);
  }
  return q;
}

VtuMesh loaded_shell_vtu(const TyreMesh& tm, const TyreDescription& tyre, const StaticContactResult& r,
                         const std::vector<ElementResult>& elements) {
  const Eigen::VectorXd& u = r.final_state.displacement;
  VtuMesh v = shell_vtu(tm, tyre, u, elements);
  const int np = tm.mesh.pair_count();
  if (static_cast<int>(v.points.size()) != 2 * np)
    throw std::logic_error(
        "loaded_shell_vtu: shell_vtu no longer lists the inner, then the outer face nodes");
  const std::vector<double> q = nodal_contact_pressure(tm, tyre, r, u);
  std::vector<double> field(2 * static_cast<std::size_t>(np), 0.0);  // inner face (points 0 … np−1): 0
  std::copy(q.begin(), q.end(), field.begin() + np);
  v.point_scalars.emplace_back("contact_pressure_MPa", std::move(field));
  return v;
}

}  // namespace tirefem
