#pragma once
// The tread as a Winkler layer between the breaker face and a rigid support (MODEL.md §4, eqs. 1–11).
//
// Tread points sit on the outer tread surface: a point of the breaker face plus the tread height hp along
// the face's normal, r0 = x_b + hp n0. A tread point moves with the breaker face, x = r0 + u_b (the tread
// offset does not rotate: the paper's kinematics, eq. 3). Its penetration into the support is g(x) (see
// road/support_surface.hpp), the tread is compressed by g and carries the pressure qn = kp g (eq. 5). The
// contact adds to the potential ½ ∫Ωc kp g² dΩ (eq. 6) over the breaker face, so its residual is
// ∫ kp g ∂g/∂u dΩ (eq. 11 with the sign of a residual) and its tangent ∫ kp (∂g ∂gᵀ + g ∂²g) dΩ (eq. 10
// plus the support's curvature term, zero on the plane): symmetric.
//
// Quadrature: an n × n Gauss rule on every breaker-face element with tread (ContactSettings::quadrature);
// each Gauss point is one tread point. With n = 4 on the 120 × 46 tyre mesh the points are ≈ 1.5 mm apart
// across the patch, so the pressure map resolves the contact edge well inside an element.
//
// Contact region Ωc: either the points with g > 0 at the current iterate (single-loop iteration), or a
// region frozen by the outer loop of the two-level iteration (the paper's), in which every point carries
// kp g whatever the sign of g, and the points outside carry nothing.
#include <array>
#include <functional>
#include <vector>

#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/road/support_surface.hpp"
#include "tirefem/solver/form.hpp"

namespace tirefem {

struct TreadPoint {
  int element = 0;
  std::array<int, 4> pairs{};  // node pairs of the element (their outer-face DOFs move the point)
  Eigen::Vector4d shape = Eigen::Vector4d::Zero();  // bilinear shape functions at the point
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();  // r0 on the tread surface
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();     // unit normal of the breaker face (reference)
  double weight = 0.0;  // breaker-face area the point stands for, mm²
  double height = 0.0;  // tread height hp at the point, mm
  double u = 0.0, v = 0.0;  // mesh parameters of the point (on the tyre: s in mm and φ in rad)
};

// Tread points of the given elements: an n × n Gauss rule on the outer face, hp(u) along the face normal
// (the direction from the inner to the outer face, interpolated). Points with hp(u) < 0 are left out
// (no tread there).
std::vector<TreadPoint> make_tread_points(const ShellMesh& mesh, const std::vector<int>& elements,
                                          int quadrature, const std::function<double(double u)>& tread_height);

// The 12 outer-face DOFs that move a tread point (its element's node pairs), and its position at u.
std::array<int, 12> tread_point_dofs(const TreadPoint& p);
Eigen::Vector3d tread_point_position(const TreadPoint& p, const Eigen::VectorXd& u);

// State of one tread point at a displacement.
struct TreadPointState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // current tread point x = r0 + u_b
  double penetration = 0.0;                             // g
  double pressure = 0.0;                                // kp max(g, 0), MPa
  Eigen::Vector3d force = Eigen::Vector3d::Zero();      // force of the support on the tyre, N
};

class WinklerContactForm final : public Form {
 public:
  WinklerContactForm(const ShellMesh& mesh, std::vector<TreadPoint> points, double stiffness,
                     const RigidSurface& support);

  void add_pattern(PatternBuilder& pattern) const override;
  void assemble(const FormInput& input, SparseSystem& system) const override;
  bool has_potential() const override { return true; }
  // Change of ½ ∫ kp g² dΩ over the points that carry load (eq. 6): a frozen region's points whatever
  // the sign of g, else those with g > 0 (⟨g⟩₊², MODEL.md §8).
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override;

  // The support's approach δz towards the axle.
  void set_deflection(double deflection) { deflection_ = deflection; }
  double deflection() const { return deflection_; }
  // Two-level iteration: from now on exactly the points marked in `region` carry the tread pressure.
  void freeze_region(std::vector<char> region);
  // Single-loop iteration: the region is {g > 0} at each iterate.
  void release_region() { frozen_.clear(); }

  const std::vector<char>& frozen_region() const { return frozen_; }  // empty when released
  double stiffness() const { return stiffness_; }
  const RigidSurface& support() const { return support_; }

  // {g > 0} at the displacement u: the region the outer loop proposes.
  std::vector<char> region(const Eigen::VectorXd& u) const;
  std::vector<TreadPointState> evaluate(const Eigen::VectorXd& u) const;

  const std::vector<TreadPoint>& points() const { return points_; }

 private:
  Eigen::Vector3d position(const TreadPoint& p, const Eigen::VectorXd& u) const;
  bool carries_load(int point, double penetration) const;

  const ShellMesh& mesh_;
  std::vector<TreadPoint> points_;
  std::vector<int> element_begin_;  // points_ sorted by element; [begin[k], begin[k+1]) of group k
  double stiffness_;
  const RigidSurface& support_;
  double deflection_ = 0.0;
  std::vector<char> frozen_;
};

}  // namespace tirefem
