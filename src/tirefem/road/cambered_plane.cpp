#include "tirefem/road/cambered_plane.hpp"

#include <cmath>
#include <stdexcept>

namespace tirefem {

void CamberedPlane::set_camber(double camber_rad) {
  if (!(std::abs(camber_rad) < 1.0)) throw std::invalid_argument("camber must be below 1 rad in magnitude");
  camber_ = camber_rad;
  sin_ = std::sin(camber_rad);
  cos_ = std::cos(camber_rad);
}

Penetration CamberedPlane::penetration(const Eigen::Vector3d& x, double deflection) const {
  // g = −n·(x − (0, 0, δz)) = (δz − z) cos γ + x sin γ.
  Penetration p;
  p.value = (deflection - x.z()) * cos_ + x.x() * sin_;
  p.gradient = Eigen::Vector3d(sin_, 0.0, -cos_);
  return p;
}

TravelCoordinate CamberedPlane::lateral(const Eigen::Vector3d& x, double deflection) const {
  TravelCoordinate t;
  t.value = x.x() * cos_ + (x.z() - deflection) * sin_;
  t.gradient = Eigen::Vector3d(cos_, 0.0, sin_);
  return t;
}

double CamberedPlane::height(double x, double, double deflection) const { return deflection + x * sin_ / cos_; }

}  // namespace tirefem
