#include "tirefem/report/tread_point_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace tirefem {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Sorted distinct values; values closer than a relative 1e-9 count as one.
std::vector<double> distinct(std::vector<double> values, double& tolerance) {
  std::sort(values.begin(), values.end());
  double scale = 1.0;
  for (double x : values) scale = std::max(scale, std::abs(x));
  tolerance = 1e-9 * scale;
  std::vector<double> out;
  for (double x : values)
    if (out.empty() || x - out.back() > tolerance) out.push_back(x);
  return out;
}

int index_of(const std::vector<double>& sorted, double x, double tolerance) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), x - tolerance);
  if (it == sorted.end() || *it > x + tolerance) throw std::logic_error("tread grid: value not found");
  return static_cast<int>(it - sorted.begin());
}

}  // namespace

TreadGrid tread_grid(const std::vector<TreadPoint>& points, bool half_model) {
  std::vector<double> us, vs;
  for (const TreadPoint& p : points) us.push_back(p.u), vs.push_back(p.v);
  double tol_u = 0.0, tol_v = 0.0;
  us = distinct(us, tol_u);
  vs = distinct(vs, tol_v);
  TreadGrid g;
  const int n0 = static_cast<int>(us.size());
  std::vector<int> column(n0), mirror_column(n0, -1);
  if (half_model)
    for (int k = n0 - 1; k >= 0; --k)
      if (us[k] > tol_u) {
        mirror_column[k] = g.nu();
        g.u.push_back(-us[k]);
        g.mirrored.push_back(1);
      }
  for (int k = 0; k < n0; ++k) {
    column[k] = g.nu();
    g.u.push_back(us[k]);
    g.mirrored.push_back(0);
  }
  g.v = vs;
  g.point.assign(static_cast<std::size_t>(g.nu()) * g.nv(), -1);
  for (int n = 0; n < static_cast<int>(points.size()); ++n) {
    const int k = index_of(us, points[n].u, tol_u), j = index_of(vs, points[n].v, tol_v);
    g.point[static_cast<std::size_t>(j) * g.nu() + column[k]] = n;
    if (mirror_column[k] >= 0) g.point[static_cast<std::size_t>(j) * g.nu() + mirror_column[k]] = n;
  }
  return g;
}

std::vector<char> patch_points(const std::vector<TreadPointState>& states) {
  std::vector<char> active(states.size(), 0);
  bool any = false;
  double g_max = -std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < states.size(); ++n) {
    if (states[n].pressure > 0) active[n] = 1, any = true;
    g_max = std::max(g_max, states[n].penetration);
  }
  if (!any)
    for (std::size_t n = 0; n < states.size(); ++n) active[n] = states[n].penetration >= g_max;
  return active;
}

TreadWindow patch_window(const TreadGrid& g, const std::vector<TreadPointState>& states, int margin) {
  const std::vector<char> active = patch_points(states);
  TreadWindow w{g.nu(), -1, g.nv(), -1};
  for (int j = 0; j < g.nv(); ++j)
    for (int i = 0; i < g.nu(); ++i) {
      const int n = g.at(i, j);
      if (n < 0 || !active[n]) continue;
      w.i0 = std::min(w.i0, i), w.i1 = std::max(w.i1, i);
      w.j0 = std::min(w.j0, j), w.j1 = std::max(w.j1, j);
    }
  w.i0 = std::max(0, w.i0 - margin), w.i1 = std::min(g.nu() - 1, w.i1 + margin);
  w.j0 = std::max(0, w.j0 - margin), w.j1 = std::min(g.nv() - 1, w.j1 + margin);
  return w;
}

void set_s_phi_axes(HeatMap& m, const TreadGrid& g, const TreadWindow& w) {
  m.x_label = "s from the equator [mm]";
  m.y_label = "φ [deg]";
  for (int i = w.i0; i <= w.i1; ++i) m.x.push_back(g.u[i]);
  for (int j = w.j0; j <= w.j1; ++j) m.y.push_back(g.v[j] * kDeg);
}

}  // namespace tirefem
