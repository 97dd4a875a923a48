#include "tirefem/mesh/shell_mesh.hpp"

#include <cmath>
#include <stdexcept>

namespace tirefem {

std::vector<int> ShellMesh::edge_pairs(GridEdge edge) const {
  std::vector<int> pairs;
  switch (edge) {
    case GridEdge::u_min:
    case GridEdge::u_max: {
      const int i = edge == GridEdge::u_min ? 0 : u_nodes() - 1;
      for (int j = 0; j < v_nodes(); ++j) pairs.push_back(pair_index(i, j));
      break;
    }
    case GridEdge::v_min:
    case GridEdge::v_max: {
      if (closed_v) throw std::invalid_argument("a mesh closed in v has no v edges");
      const int j = edge == GridEdge::v_min ? 0 : v_nodes() - 1;
      for (int i = 0; i < u_nodes(); ++i) pairs.push_back(pair_index(i, j));
      break;
    }
  }
  return pairs;
}

std::array<int, 24> ShellMesh::element_dofs(int element) const {
  std::array<int, 24> dofs{};
  const auto& e = elements[element];
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) {
      dofs[3 * a + c] = inner_dof(e[a], c);
      dofs[12 + 3 * a + c] = outer_dof(e[a], c);
    }
  return dofs;
}

Eigen::Matrix<double, 3, 8> ShellMesh::element_reference(int element) const {
  Eigen::Matrix<double, 3, 8> x;
  const auto& e = elements[element];
  for (int a = 0; a < 4; ++a) {
    x.col(a) = inner_nodes[e[a]];
    x.col(a + 4) = outer_nodes[e[a]];
  }
  return x;
}

ShellMesh build_grid_mesh(std::vector<double> u_values, std::vector<double> v_values, bool closed_v,
                          const std::function<NodePairPosition(double, double)>& position) {
  if (u_values.size() < 2 || v_values.size() < 2)
    throw std::invalid_argument("a shell mesh needs at least one element in each direction");
  ShellMesh mesh;
  mesh.u_values = std::move(u_values);
  mesh.v_values = std::move(v_values);
  mesh.closed_v = closed_v;
  const int nu = mesh.u_nodes(), nv = mesh.v_nodes();
  mesh.inner_nodes.reserve(nu * nv);
  mesh.outer_nodes.reserve(nu * nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const NodePairPosition p = position(mesh.u_values[i], mesh.v_values[j]);
      mesh.inner_nodes.push_back(p.inner);
      mesh.outer_nodes.push_back(p.outer);
    }
  for (int j = 0; j < mesh.v_elements(); ++j)
    for (int i = 0; i < mesh.u_elements(); ++i) {
      const int j1 = (closed_v && j + 1 == nv) ? 0 : j + 1;
      mesh.elements.push_back({mesh.pair_index(i, j), mesh.pair_index(i + 1, j),
                               mesh.pair_index(i + 1, j1), mesh.pair_index(i, j1)});
    }
  return mesh;
}

std::vector<double> graded_values(double a, double b, int n, double ratio) {
  if (n < 1) throw std::invalid_argument("graded_values needs n ≥ 1");
  std::vector<double> v(n + 1);
  if (std::abs(ratio - 1.0) < 1e-12 || n == 1) {
    for (int i = 0; i <= n; ++i) v[i] = a + (b - a) * i / n;
    return v;
  }
  const double q = std::pow(1.0 / ratio, 1.0 / (n - 1));  // spacing factor between neighbours
  const double first = (b - a) * (1 - q) / (1 - std::pow(q, n));
  v[0] = a;
  double step = first;
  for (int i = 1; i <= n; ++i, step *= q) v[i] = v[i - 1] + step;
  v[n] = b;
  return v;
}

}  // namespace tirefem
