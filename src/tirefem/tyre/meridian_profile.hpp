#pragma once
// The tyre's meridian (carcass line) as a smooth curve in the (x, r) half-plane, parametrised by its true
// arc length s from the equator. Built from sample points by a cubic spline in the chord-length parameter
// (then re-parametrised by arc length), with the equator end made symmetric (dr/ds = 0, d²x/ds² = 0), so
// that the mirrored bead-to-bead profile of the full model is smooth (continuous tangent and curvature)
// through the equator. The bead end uses the not-a-knot condition.
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "tirefem/mesh/revolution_mesh.hpp"

namespace tirefem {

class MeridianProfile {
 public:
  MeridianProfile() = default;  // empty; only a placeholder to assign to
  // Points (x, r) from the equator (x = 0) to the bead. Throws std::invalid_argument if there are fewer
  // than two, if the first is not at x = 0, or if two consecutive points coincide.
  explicit MeridianProfile(std::vector<Eigen::Vector2d> points);

  // Arc length range: [0, L] for a half profile, [−L, L] for a mirrored one.
  double s_begin() const { return mirrored_ ? -half_length() : 0.0; }
  double s_end() const { return half_length(); }
  double length() const { return s_end() - s_begin(); }
  bool is_mirrored() const { return mirrored_; }

  // s must lie in [s_begin(), s_end()] (1e-9 relative slack); otherwise std::out_of_range.
  Eigen::Vector2d point(double s) const;
  Eigen::Vector2d tangent(double s) const;  // unit (dx/ds, dr/ds)
  Eigen::Vector2d normal(double s) const;   // (−r', x'): away from the axis at the crown
  // Signed curvature with dt/ds = −κ n: positive where the meridian bulges along its normal (crown,
  // shoulder and sidewall of a tyre); 1/radius on a circular arc.
  double curvature(double s) const;

  // For build_revolution_mesh. The functions share this profile's data (cheap to copy, safe to outlive it).
  Meridian meridian() const;

  // The bead-to-bead profile of the full model: s from −L to L; the part at s < 0 is the mirror image
  // x → −x of the part at −s.
  MeridianProfile mirrored() const;

  // The input points and their arc lengths on the interpolated curve (half profile, from the equator).
  const std::vector<Eigen::Vector2d>& points() const;
  const std::vector<double>& point_arc_lengths() const;

 private:
  struct Spline;
  double half_length() const;
  std::shared_ptr<const Spline> spline_;
  bool mirrored_ = false;
};

}  // namespace tirefem
