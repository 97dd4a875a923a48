#include "tirefem/mesh/revolution_mesh.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tirefem {

Eigen::Vector3d revolution_point(const Eigen::Vector2d& x_r, double phi, double axis_z) {
  return {x_r[0], x_r[1] * std::sin(phi), axis_z - x_r[1] * std::cos(phi)};
}

Eigen::Vector3d revolution_normal(const Eigen::Vector2d& tangent, double phi) {
  const double nx = -tangent[1], nr = tangent[0];
  return {nx, nr * std::sin(phi), -nr * std::cos(phi)};
}

ShellMesh build_revolution_mesh(const RevolutionMeshSpec& spec) {
  if (!spec.outer_offset) throw std::invalid_argument("revolution mesh: outer_offset is not set");
  if (spec.closed) {
    const double span = spec.phi_values.back() - spec.phi_values.front();
    if (std::abs(span - 2 * std::numbers::pi) > 1e-9)
      throw std::invalid_argument("revolution mesh: a closed mesh must span 2π in φ");
  }
  return build_grid_mesh(spec.s_values, spec.phi_values, spec.closed, [&](double s, double phi) {
    const Eigen::Vector3d base = revolution_point(spec.meridian.point(s), phi, spec.axis_z);
    const Eigen::Vector3d normal = revolution_normal(spec.meridian.tangent(s), phi);
    return NodePairPosition{base + spec.inner_offset(s) * normal, base + spec.outer_offset(s) * normal};
  });
}

std::vector<double> circumferential_stations(int n, double ratio) {
  if (n < 3) throw std::invalid_argument("circumferential_stations: need at least 3 elements");
  if (ratio < 1.0) throw std::invalid_argument("circumferential_stations: ratio must be ≥ 1");
  const double c = (ratio - 1.0) / (ratio + 1.0);
  const double pi = std::numbers::pi;
  std::vector<double> phi(n + 1);
  for (int k = 0; k <= n; ++k) {
    const double t = -1.0 + 2.0 * k / n;
    phi[k] = pi * (t - c * std::sin(pi * t) / pi);
  }
  return phi;
}

}  // namespace tirefem
