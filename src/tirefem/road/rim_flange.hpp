#pragma once
// The rim flange: the bead is clamped to the rim (MODEL.md §2), and above the clamped line the lower
// sidewall leans on the flange's curl. The curl is a rigid torus about the wheel axis, a circle of radius
// R in the meridian plane, placed tangent to the outer face at the bead on the side away from the tyre (so
// the uninflated reference state just touches it there, on the tyre data's "the carcass leaves the rim
// flange" line). The full model has one at each bead, mirror images in x = 0.
//
// Penetration of a point X: with a its axial coordinate, ρ its distance from the axis and c = (cx, cr) the
// curl's centre, d = (|a| − cx, ρ − cr) and g = R − |d| (> 0 inside the curl). Its derivatives follow from
// ∂(a, ρ)/∂X = (e_x, e_ρ) and ∂²ρ/∂X² = (P_yz − e_ρ e_ρᵀ)/ρ. A rolling tyre sees the flange unchanged
// (it is axisymmetric and turns with the wheel), so the same surface serves every study; it is frictionless.
#include <vector>

#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/road/support_surface.hpp"

namespace tirefem {

class RimFlange final : public RigidSurface {
 public:
  // `centre` = (axial ≥ 0, radial) of the curl's centre; the wheel axis is parallel to x at height axis_z.
  RimFlange(Eigen::Vector2d centre, double radius, double axis_z, bool mirrored);
  Penetration penetration(const Eigen::Vector3d& x, double deflection) const override;
  // Distance of a point from the flange's surface (−g): > 0 outside the curl.
  double clearance(const Eigen::Vector3d& x) const { return -penetration(x, 0.0).value; }

  const Eigen::Vector2d& centre() const { return centre_; }
  double radius() const { return radius_; }
  double axis_z() const { return axis_z_; }

 private:
  Eigen::Vector2d centre_;
  double radius_;
  double axis_z_;
  bool mirrored_;  // a second flange at −x (the full model)
};

// The curl of radius R tangent to the mesh's outer face at the bead (grid edge u_max, at v = 0): its
// centre lies R along the outward normal of the last element's outer meridian chord.
RimFlange place_rim_flange(const ShellMesh& mesh, double axis_z, bool mirrored, double radius);

// Elements whose reference outer face comes within one curl radius of the flange (clearance < R at one
// of its outer nodes): the only ones the flange can meet unless the sidewall folds over it.
std::vector<int> elements_near_flange(const ShellMesh& mesh, const RimFlange& flange);

}  // namespace tirefem
