#pragma once
// Shells of revolution about an axis parallel to x. A meridian point (x, r) at angle φ sits at
//   (x, r sin φ, axis_z − r cos φ),
// so φ = 0 is the lowest point (the centre of the contact patch on a tyre) and z points from the road to
// the axle (MODEL.md §2). The meridian is parametrised by arc length s.
#include <functional>

#include "tirefem/mesh/shell_mesh.hpp"

namespace tirefem {

struct Meridian {
  std::function<Eigen::Vector2d(double s)> point;    // (x, r)
  std::function<Eigen::Vector2d(double s)> tangent;  // unit (dx/ds, dr/ds)
};

struct RevolutionMeshSpec {
  Meridian meridian;
  std::vector<double> s_values;     // meridian stations (element edges), increasing
  std::vector<double> phi_values;   // circumferential stations, radians, increasing
  bool closed = true;               // phi_values spans 2π and wraps around
  double axis_z = 0.0;
  // Signed offsets of the inner and outer face from the meridian along the normal (−r', x'),
  // which points away from the axis on a tyre's crown.
  std::function<double(double s)> inner_offset = [](double) { return 0.0; };
  std::function<double(double s)> outer_offset;
};

ShellMesh build_revolution_mesh(const RevolutionMeshSpec& spec);

// Meridian normal (−r', x') lifted to 3D at angle φ.
Eigen::Vector3d revolution_normal(const Eigen::Vector2d& tangent, double phi);
Eigen::Vector3d revolution_point(const Eigen::Vector2d& x_r, double phi, double axis_z);

// n circumferential stations over [−π, π], refined around φ = 0: the element at φ = 0 is `ratio` times
// shorter than the one at φ = ±π (smooth map φ = π(t − c sin(πt)/π), c = (ratio − 1)/(ratio + 1)).
std::vector<double> circumferential_stations(int n, double ratio);

}  // namespace tirefem
