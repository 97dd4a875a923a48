#include "tirefem/analysis/mesh_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace tirefem {

namespace {
// φ of a node pair's reference point (x, r sin φ, axis_z − r cos φ) (mesh/revolution_mesh.hpp).
double node_angle(const TyreMesh& tm, int pair) {
  const Eigen::Vector3d& p = tm.mesh.inner_nodes[pair];
  return std::atan2(p.y(), tm.axis_z - p.z());
}

// For each node column of `to`, the column of `from` at the same meridional station (on a full `to` from a
// half `from`: at |s|, the mirror image for s < 0); empty when there is none for some column.
std::vector<int> matching_columns(const TyreMesh& from, const TyreMesh& to) {
  const bool mirror = from.half_model && !to.half_model;
  if (from.half_model != to.half_model && !mirror) return {};
  std::vector<int> columns;
  const std::vector<double>& f = from.mesh.u_values;
  for (double s : to.mesh.u_values) {
    const double station = mirror ? std::abs(s) : s;
    const auto it = std::find_if(f.begin(), f.end(), [&](double g) { return std::abs(g - station) <= 1e-9 * (1 + std::abs(g)); });
    if (it == f.end()) return {};
    columns.push_back(static_cast<int>(it - f.begin()));
  }
  // Every station of `from` is used (no coarser `to` taking a subset): the meshes have the same stations.
  std::vector<char> used(f.size(), 0);
  for (int c : columns) used[c] = 1;
  if (std::find(used.begin(), used.end(), 0) != used.end()) return {};
  return columns;
}
}  // namespace

bool turns_onto(const TyreMesh& from, const TyreMesh& to) { return !matching_columns(from, to).empty(); }

Eigen::VectorXd turned_onto(const TyreMesh& from, const Eigen::VectorXd& displacement, const TyreMesh& to) {
  const std::vector<int> columns = matching_columns(from, to);
  if (columns.empty()) throw std::invalid_argument("turned_onto: the meshes' meridional stations differ");
  // φ of a point (x, r sin φ, axis_z − r cos φ) (mesh/revolution_mesh.hpp); a rotation by Δ about x
  // takes φ to φ + Δ, and so the displacement of a node row onto a row Δ further round. A column at s < 0
  // of a full mesh from a half one: the mirror image in the wheel plane (x → −x), then the turn.
  // A full model from its half on the same circumferential stations: each row takes its own (no turn),
  // exact where the state is not quite axisymmetric (elements refined towards the patch).
  const bool mirror = from.half_model && !to.half_model;
  const bool same_rows = mirror && from.mesh.v_values == to.mesh.v_values;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(to.mesh.dof_count());
  for (int j = 0; j < to.mesh.v_nodes(); ++j)
    for (int i = 0; i < to.mesh.u_nodes(); ++i) {
      const int p = to.mesh.pair_index(i, j), q = from.mesh.pair_index(columns[i], same_rows ? j : 0);
      const double turn = node_angle(to, p) - node_angle(from, q);
      Eigen::Matrix3d r = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitX()).toRotationMatrix();
      if (mirror && to.mesh.u_values[i] < 0) r.col(0) *= -1.0;
      u.segment<3>(6 * p) = r * displacement.segment<3>(6 * q);
      u.segment<3>(6 * p + 3) = r * displacement.segment<3>(6 * q + 3);
    }
  return u;
}

bool mirrors_onto(const TyreMesh& from, const TyreMesh& to) {
  return from.half_model && !to.half_model && from.mesh.v_values == to.mesh.v_values && turns_onto(from, to);
}

Eigen::VectorXd mirrored_onto(const TyreMesh& from, const Eigen::VectorXd& displacement, const TyreMesh& to) {
  if (!mirrors_onto(from, to))
    throw std::invalid_argument("mirrored_onto: not a half model onto the full model of its stations");
  return turned_onto(from, displacement, to);  // on the same rows: each row its own (see there)
}

bool interpolates_onto(const TyreMesh& from, const TyreMesh& to) {
  return from.half_model == to.half_model && !matching_columns(from, to).empty();
}

Eigen::VectorXd interpolated_onto(const TyreMesh& from, const Eigen::VectorXd& displacement, const TyreMesh& to) {
  if (!interpolates_onto(from, to))
    throw std::invalid_argument("interpolated_onto: the meshes' kinds or meridional stations differ");
  const std::vector<int> columns = matching_columns(from, to);
  // The angles of `from`'s node rows, unwrapped to increase over one turn from the first.
  constexpr double kTurn = 2.0 * std::numbers::pi;
  const int rows = from.mesh.v_nodes();
  std::vector<double> angle(rows);
  for (int j = 0; j < rows; ++j) {
    angle[j] = node_angle(from, from.mesh.pair_index(0, j));
    if (j > 0)
      while (angle[j] <= angle[j - 1]) angle[j] += kTurn;
  }
  Eigen::VectorXd u = Eigen::VectorXd::Zero(to.mesh.dof_count());
  for (int j = 0; j < to.mesh.v_nodes(); ++j) {
    // The rows of `from` on either side of this row's angle (across the first row, the last and the first).
    double phi = node_angle(to, to.mesh.pair_index(0, j));
    phi = angle[0] + std::fmod(std::fmod(phi - angle[0], kTurn) + kTurn, kTurn);
    const int below = static_cast<int>(std::upper_bound(angle.begin(), angle.end(), phi) - angle.begin()) - 1;
    const int above = (below + 1) % rows;
    const double upper = below + 1 < rows ? angle[below + 1] : angle[0] + kTurn;
    const double w = (phi - angle[below]) / (upper - angle[below]);
    const Eigen::Matrix3d turn_below = Eigen::AngleAxisd(phi - angle[below], Eigen::Vector3d::UnitX()).toRotationMatrix();
    const Eigen::Matrix3d turn_above = Eigen::AngleAxisd(phi - upper, Eigen::Vector3d::UnitX()).toRotationMatrix();
    for (int i = 0; i < to.mesh.u_nodes(); ++i) {
      const int p = to.mesh.pair_index(i, j);
      const int a = from.mesh.pair_index(columns[i], below), b = from.mesh.pair_index(columns[i], above);
      for (int face = 0; face < 2; ++face)
        u.segment<3>(6 * p + 3 * face) = (1.0 - w) * turn_below * displacement.segment<3>(6 * a + 3 * face) +
                                         w * turn_above * displacement.segment<3>(6 * b + 3 * face);
    }
  }
  return u;
}

}  // namespace tirefem
