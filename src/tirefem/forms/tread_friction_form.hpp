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
// u; released, the plan follows the iterate (single loop). Frozen or released, an entry anchor's weight
// between its two points (where g crosses zero, entry_weight) follows u: a frozen plan holds the points'
// status and which points their anchors lie between, not where the patch's edge lies between them.
//
// Planar mode (MODEL.md §7, slip angle; set_planar): the shear is a 2-vector with components along
// t = ∇ξ/|∇ξ| and b = ∇η/|∇η| (η the support's lateral coordinate), and the support also drifts by d along
// +η per unit of travel along ξ (set_lateral_drift):
//     s = s_A + Rk (ψ − ψ_A) (1, d) − (ξ − ξ_A, η − η_A),
// stick where (G/hp)|s| ≤ μ kp g, else slip with the traction μ kp g s/|s| (isotropic Coulomb) and the
// shear (μ kp g hp/G) s/|s|. A slip point's trial shear is measured from its own anchor, so the tangent of
// a slip point or of a point re-sticking behind it chains upstream along the line to the patch entry
// (tread_friction_planar.cpp). Off (the default), the form is the paper's 1D model above, unchanged.
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
  double sign = 0.0;                 // slip: σ (planar: the sign of the trial shear's t-component)
  // Planar mode: a Coulomb slip point's anchor fields are set too (its trial shear is measured from it).
};
using FrictionPlan = std::vector<FrictionPlanPoint>;

// Tangential state of one tread point.
struct TreadTraction {
  TreadContact status = TreadContact::out;
  double shear = 0.0;     // s: tip minus base along the support's motion, mm
  double traction = 0.0;  // qt: tangential stress on the tyre along the support's motion, MPa
  // Components along (t, b) (planar mode; 1D: (shear, 0) and (traction, 0)).
  Eigen::Vector2d shear_vector = Eigen::Vector2d::Zero();     // mm
  Eigen::Vector2d traction_vector = Eigen::Vector2d::Zero();  // MPa
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // tangential force on the tyre, N
};

// The weight of the stick tangent in a sliding point's smoothed tangent (TreadFrictionForm::
// set_jacobian_smoothing): 1 at and below the friction-limited shear L (a frozen plan's sliding point may
// lie below it at a later iterate), falling linearly to 0 at |s| = (1 + band) L, 0 beyond; 0 for band 0.
double stick_tangent_weight(double shear_norm, double limit, double band);

// Where the penetration crosses zero between the last point out of the patch (g_out) and the first in it
// (g_in), as the weight of the latter: the entry anchor is (1 − w)·out + w·in, w in [0, 1].
double entry_weight(double g_out, double g_in);

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
  // Planar (2D) tread shear (MODEL.md §7); false: the paper's 1D model. Changing it invalidates a frozen
  // plan (a planar plan records the anchors of slip points too): freeze a plan made in the same mode.
  void set_planar(bool planar) { planar_ = planar; }
  bool planar() const { return planar_; }
  // d: the support's displacement along +η per unit of its travel along ξ (planar mode only).
  void set_lateral_drift(double drift) { drift_ = drift; }
  double lateral_drift() const { return drift_; }
  // Planar mode, Newton's direction only: a sliding point with |s| between L and (1 + band) L (L the
  // friction-limited shear) gets a blend of its stick and slip tangents instead of the slip one. The
  // residual stays exact; the tangent is not its derivative there. 0 (default): the exact tangent. Near
  // the limit the exact tangent swings between stick and slip from one iterate to the next (a chain of
  // points along a line re-sticking and sliding), and Newton cycles.
  void set_jacobian_smoothing(double band) { jacobian_smoothing_ = band; }
  double jacobian_smoothing() const { return jacobian_smoothing_; }

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
  // Position, travel coordinate, lateral coordinate (planar mode) and penetration of a tread point, the
  // travel coordinate counted along the support's motion (ξ_d = direction · ξ).
  struct PointKinematics {
    Eigen::Vector3d position;
    TravelCoordinate travel;
    TravelCoordinate lateral;
    Penetration penetration;
  };
  struct PlanarPoint;
  // 1D mode: the force on the tyre of a point in contact (eq. 17) and its derivatives w.r.t. the
  // positions of the point itself and of its anchor's points a and b (other: −1 when none).
  struct PointForce {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    Eigen::Matrix3d d_self = Eigen::Matrix3d::Zero();
    int other[2] = {-1, -1};
    Eigen::Matrix3d d_other[2] = {Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};
  };
  PointForce point_force(int q, const FrictionPlanPoint& pp, const Eigen::VectorXd& u) const;
  PointKinematics kinematics(int point, const Eigen::VectorXd& u) const;
  double flow_angle(int point) const { return direction_ * points_[point].v; }
  double slip_shear(int point, double penetration, double sign) const;

  // Planar mode (tread_friction_planar.cpp).
  FrictionPlan plan_planar(const Eigen::VectorXd& u, const std::vector<char>& region) const;
  void assemble_planar(const FormInput& input, SparseSystem& system) const;
  std::vector<TreadTraction> evaluate_planar(const Eigen::VectorXd& u) const;
  // Marches along line `l` with `plan`; fills per point of the line (in line order) its traction and,
  // with `derivatives`, the derivative of its force on the tyre w.r.t. the positions of the line's points
  // first, ..., first + W − 1 (3 × 3W), `first` returned.
  int march_planar(int l, const FrictionPlan& plan, const Eigen::VectorXd& u, bool derivatives,
                   std::vector<PlanarPoint>& out) const;
  // Elements whose DOFs a point's planar force depends on (its own first), per point (empty: out).
  std::vector<std::vector<int>> planar_dependencies(const FrictionPlan& plan) const;

  const ShellMesh& mesh_;
  std::vector<TreadPoint> points_;
  std::vector<std::vector<int>> lines_;
  std::vector<int> line_position_;  // per point: its index in its line
  // Lines through the same elements (a strip of elements: one line per Gauss row), in line order. A
  // point's force depends on points of its own line only: the tangent is summed per pair of a strip's
  // elements (forms/strip_blocks.hpp).
  std::vector<std::vector<int>> strips_;
  double kp_, shear_modulus_;
  const SupportSurface& support_;
  double direction_;  // ±1: the support moves in direction_ · y
  std::vector<char> window_;
  double deflection_ = 0.0;
  double rolling_radius_ = 0.0;
  FrictionLaw law_;
  FrictionPlan frozen_;
  bool planar_ = false;
  double drift_ = 0.0;
  double jacobian_smoothing_ = 0.0;
};

}  // namespace tirefem
