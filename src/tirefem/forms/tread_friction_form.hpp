#pragma once
// Tangential tread forces of steady slow rolling with Coulomb stick and slip (MODEL.md §5, eqs. 15–17).
//
// Fixed axle, the support moves under the tyre; the tyre's state is stationary in space, the tread
// material flows through it along circumferential lines of tread points (equal s, ordered by φ in the
// direction of the flow). A tread block enters the patch unsheared and its tip then moves with the
// support while its base moves with the breaker: along the line, in the stick zone, the shear (tip minus
// base, mm, along the support's motion) is (eq. 16)
//     s_k = s_A + Rk (ψ_k − ψ_A) − (ξ_k − ξ_A),
// with ψ the angle along the flow, ξ the travel coordinate of the tread point (road/support_surface.hpp,
// counted along the support's motion), Rk = V/Ω the rolling radius, and A the anchor: the entry of the
// patch (interpolated between the last point out of and the first point in contact, s_A = 0) or, after a
// slip zone, the last sliding point (re-sticking: s_A is that point's friction-limited shear). The tread
// then pulls the breaker with G s/hp per unit area along the support's motion t ([Kst], {Fst}). Where
// G|s|/hp would exceed μ qn = μ kp g (eq. 15) the point slides: the traction is σ μ kp g t, σ the sign of
// the would-be stick shear ([Ksl], {Fsl}: depends on the normal displacement through g, not on the
// tangential one: unsymmetric). The stick shear of a point depends on the displacement of its anchor too,
// so the tangent couples points along a line (still unsymmetric): the pattern holds blocks for every pair
// of elements of a strip inside the friction window, the tread points that may touch the support.
//
// The stick / slip / out status of the points and the anchors form a plan. A frozen plan (the outer loop
// of the two-level iteration, with the Winkler form's region frozen alike) makes the residual smooth in
// u; released, the plan follows the iterate (single loop).
#include <vector>

#include "tirefem/forms/winkler_contact_form.hpp"

namespace tirefem {

enum class TreadContact : char { out, stick, slip };

struct FrictionLaw {
  enum class Mode { coulomb, full_stick, full_slip };
  Mode mode = Mode::coulomb;
  double friction = 0.7;  // μ (coulomb, full_slip)
  double slip_sign = 1.0; // full_slip: σ, the sign of the traction along the support's motion
};

// Status of one tread point and what its shear is measured from.
struct FrictionPlanPoint {
  TreadContact status = TreadContact::out;
  int anchor_a = -1, anchor_b = -1;  // stick: ψ_A, ξ_A = (1 − w)·(point a) + w·(point b)
  double anchor_weight = 0.0;
  bool anchored_on_slip = false;     // stick after slip: a = b = the last sliding point
  double sign = 0.0;                 // slip: σ
};
using FrictionPlan = std::vector<FrictionPlanPoint>;

// Tangential state of one tread point.
struct TreadTraction {
  TreadContact status = TreadContact::out;
  double shear = 0.0;     // s: tip minus base along the support's motion, mm
  double traction = 0.0;  // qt: tangential stress on the tyre along the support's motion, MPa
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // tangential force on the tyre, N
};

class TreadFrictionForm final : public Form {
 public:
  // `points` in the order of the Winkler form (WinklerContactForm::points()); `shear_modulus` G of the
  // tread rubber; `support_direction` +1 when the support moves in +y under the tyre, −1 for −y;
  // `window`: per point, whether it may touch the support (its elements get the coupling pattern).
  TreadFrictionForm(const ShellMesh& mesh, std::vector<TreadPoint> points, double tread_stiffness,
                    double shear_modulus, const SupportSurface& support, int support_direction,
                    std::vector<char> window);

  void add_pattern(PatternBuilder& pattern) const override;
  void assemble(const FormInput& input, SparseSystem& system) const override;
  bool symmetric() const override { return false; }

  void set_deflection(double deflection) { deflection_ = deflection; }
  void set_rolling_radius(double radius) { rolling_radius_ = radius; }
  double rolling_radius() const { return rolling_radius_; }
  void set_law(const FrictionLaw& law) { law_ = law; }
  const FrictionLaw& law() const { return law_; }

  // The plan at u for a contact region (per point; empty: {g > 0} at u), by marching along each line
  // in the direction of the flow with the return mapping of eq. (15).
  FrictionPlan plan(const Eigen::VectorXd& u, const std::vector<char>& region = {}) const;
  void freeze_plan(FrictionPlan plan);
  void release_plan() { frozen_.clear(); }

  // Tractions at u with the frozen plan, or the plan at u when released.
  std::vector<TreadTraction> evaluate(const Eigen::VectorXd& u) const;
  // Points in contact at u that lie outside the window (they carry no friction: the window is too small).
  int contact_outside_window(const Eigen::VectorXd& u) const;

  const std::vector<TreadPoint>& points() const { return points_; }
  // Lines of points (indices), each in the order of the flow.
  const std::vector<std::vector<int>>& lines() const { return lines_; }

 private:
  struct PointKinematics;
  PointKinematics kinematics(int point, const Eigen::VectorXd& u) const;
  double flow_angle(int point) const { return direction_ * points_[point].v; }
  double slip_shear(int point, double penetration, double sign) const;

  const ShellMesh& mesh_;
  std::vector<TreadPoint> points_;
  std::vector<std::vector<int>> lines_;
  double kp_, shear_modulus_;
  const SupportSurface& support_;
  double direction_;  // ±1: the support moves in direction_ · y
  std::vector<char> window_;
  double deflection_ = 0.0;
  double rolling_radius_ = 0.0;
  FrictionLaw law_;
  FrictionPlan frozen_;
};

}  // namespace tirefem
