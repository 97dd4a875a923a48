#pragma once
// The road plane seen from a cambered wheel (MODEL.md §7): the wheel plane x = 0 tilted by the camber γ
// relative to the road normal is, in the wheel's frame, the road plane turned by −γ about the y axis
// through the point under the axle (0, 0, δz): normal n = (−sin γ, 0, cos γ), so z = δz + x tan γ on it.
// γ > 0 (ISO 8855: the top of the wheel leaning to the right of its heading, towards +x) raises the road
// under the tyre's +x shoulder. The penetration is the exact distance to the plane; the travel coordinate
// is y (the inclined road translates along y unchanged) and the lateral one the distance across the road
// in its plane, along (cos γ, 0, sin γ), orthogonal to the travel direction and to n. At γ = 0 every value
// equals RoadPlane's exactly.
#include "tirefem/road/support_surface.hpp"

namespace tirefem {

class CamberedPlane final : public SupportSurface {
 public:
  explicit CamberedPlane(double camber_rad = 0.0) { set_camber(camber_rad); }
  void set_camber(double camber_rad);
  double camber() const { return camber_; }

  Penetration penetration(const Eigen::Vector3d& x, double deflection) const override;
  TravelCoordinate lateral(const Eigen::Vector3d& x, double deflection) const override;
  double height(double x, double y, double deflection) const override;

 private:
  double camber_ = 0.0, sin_ = 0.0, cos_ = 1.0;
};

}  // namespace tirefem
