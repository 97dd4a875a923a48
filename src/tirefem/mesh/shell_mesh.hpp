#pragma once
// A structured mesh of three-layer shell elements: a grid of node pairs (inner face node, outer face node)
// over parameters (u, v); u runs along the element's ξ direction (the meridian on a tyre), v along η (the
// circumference). Degrees of freedom of node pair p: inner face 6p..6p+2, outer face 6p+3..6p+5.
#include <array>
#include <functional>
#include <vector>

#include <Eigen/Dense>

namespace tirefem {

enum class GridEdge { u_min, u_max, v_min, v_max };

struct ShellMesh {
  std::vector<Eigen::Vector3d> inner_nodes;  // reference positions, one per node pair
  std::vector<Eigen::Vector3d> outer_nodes;
  std::vector<std::array<int, 4>> elements;  // node-pair indices, counter-clockwise in (u, v)
  std::vector<double> u_values;              // grid parameters of the node columns / rows
  std::vector<double> v_values;              // for closed_v the last value (period) has no nodes
  bool closed_v = false;

  int u_nodes() const { return static_cast<int>(u_values.size()); }
  int v_nodes() const { return static_cast<int>(v_values.size()) - (closed_v ? 1 : 0); }
  int u_elements() const { return u_nodes() - 1; }
  int v_elements() const { return static_cast<int>(v_values.size()) - 1; }
  int pair_count() const { return static_cast<int>(inner_nodes.size()); }
  int element_count() const { return static_cast<int>(elements.size()); }
  int dof_count() const { return 6 * pair_count(); }
  int pair_index(int i_u, int j_v) const { return j_v * u_nodes() + i_u; }
  int element_index(int i_u, int j_v) const { return j_v * u_elements() + i_u; }

  std::vector<int> edge_pairs(GridEdge edge) const;
  // The 24 DOFs of an element in element order (inner face nodes 0–3, then outer face nodes 4–7).
  std::array<int, 24> element_dofs(int element) const;
  // Columns: reference positions of the element's 8 nodes.
  Eigen::Matrix<double, 3, 8> element_reference(int element) const;
};

inline int inner_dof(int pair, int component) { return 6 * pair + component; }
inline int outer_dof(int pair, int component) { return 6 * pair + 3 + component; }

struct NodePairPosition {
  Eigen::Vector3d inner, outer;
};

// Grid mesh over u_values × v_values. If closed_v, v_values spans one full period and the last row of
// nodes coincides with the first (elements wrap around).
ShellMesh build_grid_mesh(std::vector<double> u_values, std::vector<double> v_values, bool closed_v,
                          const std::function<NodePairPosition(double u, double v)>& position);

// n + 1 values from a to b; `ratio` > 1 grades them so the spacing at `a` is ratio × the spacing at `b`
// (geometric progression).
std::vector<double> graded_values(double a, double b, int n, double ratio = 1.0);

}  // namespace tirefem
