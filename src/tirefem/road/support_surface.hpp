#pragma once
// Rigid support surfaces (MODEL.md §4): the road plane, the test drum and a smooth shallow road
// z = f(x, y), each moved towards the fixed axle by the deflection δz. One question is asked of them: how
// far a point lies inside the support (the penetration g, > 0 inside), with its first and second
// derivatives, so that the contact force kp g ∂g/∂x and its exact tangent follow.
//
// Coordinates: x along the wheel axis, y in the direction of travel, z from the road up to the axle; the
// undeformed tyre touches z = 0 at the origin.
#include <memory>
#include <string>

#include <Eigen/Dense>

#include "tirefem/case/case.hpp"

namespace tirefem {

struct Penetration {
  double value = 0.0;                                       // g (mm), > 0 inside the support
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();       // ∂g/∂x: −(the support's normal)
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();        // ∂²g/∂x²
};

// Where a point lies along the support's motion in steady rolling (MODEL.md §5): the arc length ξ of its
// projection on the support, measured along the direction in which the support moves when it moves in
// +y under the tyre, with derivatives. Plane and road: ξ = y; drum: R × the angle about the drum axis.
struct TravelCoordinate {
  double value = 0.0;
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();  // ∂ξ/∂x: along the support's motion (|·| ≈ 1)
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
};

// Any rigid surface a Winkler layer can be pressed against (forms/winkler_contact_form.hpp): the road
// supports below and the rim flange (road/rim_flange.hpp).
class RigidSurface {
 public:
  virtual ~RigidSurface() = default;
  // Penetration of the point x; a support moved up by `deflection` (a surface fixed to the axle ignores it).
  virtual Penetration penetration(const Eigen::Vector3d& x, double deflection) const = 0;
};

class SupportSurface : public RigidSurface {
 public:
  // Travel coordinate of x (the road translates in y, the drum turns about its axis).
  virtual TravelCoordinate travel(const Eigen::Vector3d& x, double deflection) const;
  // Lateral coordinate η of x (MODEL.md §7): across the support's motion in the support surface, so that
  // (ξ, η) are coordinates on it. Default η = x (gradient e_x, Hessian 0): right for the plane, the drum
  // (axis parallel to x) and the translating road; an inclined (cambered) road overrides it.
  virtual TravelCoordinate lateral(const Eigen::Vector3d& x, double deflection) const;
  // Height of the support surface above (x, y) (for drawing it), with the same deflection.
  virtual double height(double x, double y, double deflection) const = 0;
};

// z = δz: the gap is exact and linear in the displacement (eq. 1 with ψ = 0).
class RoadPlane final : public SupportSurface {
 public:
  Penetration penetration(const Eigen::Vector3d& x, double deflection) const override;
  double height(double x, double y, double deflection) const override;
};

// A cylinder of radius R below the tyre, its axis parallel to x through (y = 0, z = δz − R). The
// penetration is the exact distance to the cylinder along its radius, R − |(y, z − zc)|, not the paper's
// linearisation of it (MODEL.md §4 allows either): its curvature term enters the tangent.
class TestDrum final : public SupportSurface {
 public:
  explicit TestDrum(double radius);
  Penetration penetration(const Eigen::Vector3d& x, double deflection) const override;
  TravelCoordinate travel(const Eigen::Vector3d& x, double deflection) const override;
  double height(double x, double y, double deflection) const override;
  double radius() const { return radius_; }

 private:
  double radius_;
};

// z = f(x, y) + δz with f a polynomial Σ c x^i y^j; the penetration is the vertical one,
// g = f(x, y) + δz − z (eq. 1 before linearisation), whose gradient (ψx, ψy, −1) is the paper's −n.
// Steady rolling on it makes sense only when f does not depend on y (a road that translates in y stays
// the same road): depends_on_travel() says whether it does.
class PolynomialRoad final : public SupportSurface {
 public:
  explicit PolynomialRoad(std::vector<SupportDescription::Term> terms);
  Penetration penetration(const Eigen::Vector3d& x, double deflection) const override;
  bool depends_on_travel() const;
  double height(double x, double y, double deflection) const override;

 private:
  std::vector<SupportDescription::Term> terms_;
};

std::unique_ptr<SupportSurface> make_support(const SupportDescription& description);

// "plane", "drum", "surface".
const char* support_kind_name(SupportDescription::Kind kind);
// For titles and messages: "plane", "drum 1830 mm", "surface".
std::string support_label(const SupportDescription& support);

}  // namespace tirefem
