// Inflated shells of revolution (VERIFICATION.md §1): the membrane resultants follow from equilibrium
// alone, whatever the lay-up: closed cylinder N_θ = pR, N_x = pR/2; sphere N = pR/2; torus
// N_θ = pa/2, N_φ = pa(r0 + b)/(2 r0) (p = 0.2, a = 60, b = 230: N_θ = 6.00, N_φ = 10.76 / 12.00 /
// 14.12 at the outer equator / crown / inner equator). The resultant is the sum over both faces.
// Three-layer shell with equal orthotropic (cord-like) faces and a thin, soft interlayer, linear
// theory; the inner face (which carries the pressure) lies on the reference surface and the outer face
// 0.1 mm outside it, so the two faces' radii differ by ≤ 0.17% of the smallest radius of curvature (the
// formulas do not say which face's radius to use; that ambiguity is ≤ 0.17%). Tolerance 1%, as the
// brief asks, away from loaded edges. With isotropic faces the radial growth of cylinder and sphere
// is checked too (w = pR²(1 − ν/2)/(Et), pR²(1 − ν)/(2Et)).
// The torus needs a fine circumferential mesh: at the equators N_θ/r0 is only 10% of p in the normal
// equilibrium N_φ/a ± N_θ/r0 = p, so the O(Δφ²) faceting error of the other term is amplified ~10×
// (5° elements: N_θ 1.5% off; 2.5°: 0.5%; 1.25°: 0.2%). Near the crown (r0 = b) the membrane solution
// of the torus is not compatible and the shell bends: N_θ deviates there by up to 0.8% with this
// 0.1 mm core (1.1% with 0.2 mm), a physical effect of the shell's bending stiffness, not an error.
#include <cstdio>

#include <gtest/gtest.h>

#include "tirefem/forms/nodal_load_form.hpp"
#include "tirefem/forms/pressure_form.hpp"
#include "verification_support.hpp"

namespace tirefem::verification {
namespace {

constexpr double kPressure = 0.2;
constexpr double kCoreThickness = 0.1;

ElementSection cord_like_section() {
  ElementSection s;
  s.inner_face << 3000, 600, 0, 600, 2000, 0, 0, 0, 500;  // N/mm, axis 1 = meridian
  s.outer_face = s.inner_face;
  s.core_shear_modulus = 1.0;
  s.core_normal_modulus = 10.0;
  return s;
}

// Sum of both faces' resultants [N11, N22] (axis 1 along the meridian) at the centre of element e.
Eigen::Vector2d face_sum(const ShellMesh& mesh, const std::vector<ElementSection>& sections,
                         const Eigen::VectorXd& u, int e) {
  const ElementPointState st = three_layer_point_state(
      mesh.element_reference(e), element_current(mesh, e, u), sections[e], Kinematics::linear, 0.0, 0.0);
  return (st.inner_resultant + st.outer_resultant).head<2>();
}

// Equilibrium edge load at the u_max edge of a shell of revolution: a meridional tension `n` per unit
// length of the inner face's edge circle, along the meridian tangent, half on each face.
void add_meridional_edge_load(const ShellMesh& mesh, const Meridian& meridian, double n,
                              Eigen::VectorXd& f) {
  const int i = mesh.u_nodes() - 1;
  const Eigen::Vector2d t = meridian.tangent(mesh.u_values[i]);
  const int nv = mesh.v_nodes();
  const int segments = mesh.v_elements();
  for (int j = 0; j < segments; ++j) {
    const int a = mesh.pair_index(i, j), b = mesh.pair_index(i, (j + 1) % nv);
    const double length = (mesh.inner_nodes[b] - mesh.inner_nodes[a]).norm();
    for (int k : {a, b}) {
      const double phi = mesh.v_values[k == a ? j : j + 1];
      const Eigen::Vector3d dir(t[0], t[1] * std::sin(phi), -t[1] * std::cos(phi));
      add_split_force(f, k, 0.5 * n * length * dir);
    }
  }
}

Eigen::VectorXd solve_inflation(const ShellMesh& mesh, const std::vector<ElementSection>& sections,
                                const DofMap& dofs, const Eigen::VectorXd& edge_loads) {
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::linear));
  forms.push_back(std::make_unique<PressureForm>(mesh, all_elements(mesh), kPressure, Kinematics::linear, true));
  if (edge_loads.size() > 0) forms.push_back(std::make_unique<NodalLoadForm>(edge_loads));
  NonlinearProblem problem(dofs, std::move(forms));
  return solve_linear(problem);
}

double relative_error(double value, double exact) { return std::abs(value / exact - 1.0); }

struct Inflated {
  ShellMesh mesh;
  std::vector<ElementSection> sections;
  Eigen::VectorXd u;
};

// Closed in φ (72 elements around), x ∈ [0, 200] with symmetry at x = 0 and the cap's axial force
// pR/2 per unit length applied at x = 200; planes y = 0 and z = 0 are symmetry planes.
constexpr double kRadius = 100.0;

Inflated inflate_cylinder(const ElementSection& section) {
  Inflated r;
  r.mesh = closed_cylinder_mesh(kRadius, 200.0, 10, 72, 0.0, kCoreThickness);
  const ShellMesh& mesh = r.mesh;
  r.sections.assign(mesh.element_count(), section);
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0}));
  for (int i = 0; i < mesh.u_nodes(); ++i) {
    dofs.fix(both_faces({mesh.pair_index(i, 0), mesh.pair_index(i, 36)}, {1}));   // φ = −π, 0: plane y = 0
    dofs.fix(both_faces({mesh.pair_index(i, 18), mesh.pair_index(i, 54)}, {2}));  // φ = ∓π/2: plane z = 0
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  add_meridional_edge_load(mesh, cylinder_meridian(kRadius), kPressure * kRadius / 2, f);
  r.u = solve_inflation(mesh, r.sections, dofs, f);
  return r;
}

// Sphere R = 100 from the equator (symmetry plane x = 0) to latitude 60°, where the meridional
// tension pR/2 of the missing cap is applied; quarter in φ with symmetry planes y = 0 and z = 0.
Inflated inflate_sphere_band(const ElementSection& section) {
  Inflated r;
  const Meridian meridian = sphere_meridian(kRadius);
  r.mesh = revolution_mesh(meridian, uniform_values(0, kRadius * degrees(60), 24), uniform_values(0, kPi / 2, 18),
                           false, 0.0, kCoreThickness);
  const ShellMesh& mesh = r.mesh;
  r.sections.assign(mesh.element_count(), section);
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0}));
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::v_min), {1}));
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::v_max), {2}));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  add_meridional_edge_load(mesh, meridian, kPressure * kRadius / 2, f);
  r.u = solve_inflation(mesh, r.sections, dofs, f);
  return r;
}

// Isotropic faces for the radial growth: E t = 1000 N/mm each (Et = 2000 for the wall), ν = 0.3.
ElementSection isotropic_faces() {
  ElementSection s = cord_like_section();
  s.inner_face = isotropic_membrane(1000.0, 0.3, 1.0);
  s.outer_face = s.inner_face;
  return s;
}

TEST(MembranesOfRevolution, ClosedCylinder) {
  const Inflated r = inflate_cylinder(cord_like_section());
  const ShellMesh& mesh = r.mesh;
  const double n_hoop = kPressure * kRadius, n_axial = kPressure * kRadius / 2;
  double worst_hoop = 0, worst_axial = 0;
  for (int j = 0; j < mesh.v_elements(); ++j)
    for (int i = 0; i < mesh.u_elements(); ++i) {
      const Eigen::Vector2d n = face_sum(mesh, r.sections, r.u, mesh.element_index(i, j));
      worst_axial = std::max(worst_axial, relative_error(n[0], n_axial));
      worst_hoop = std::max(worst_hoop, relative_error(n[1], n_hoop));
    }
  const Eigen::Vector2d mid = face_sum(mesh, r.sections, r.u, mesh.element_index(4, 10));
  std::printf("  cylinder R=100: N_x %.4f (exact %.4f), N_theta %.4f (exact %.4f); worst errors %.3f%%, %.3f%%\n",
              mid[0], n_axial, mid[1], n_hoop, 100 * worst_axial, 100 * worst_hoop);
  EXPECT_LT(worst_axial, 0.01) << "closed cylinder N_x = pR/2 (VERIFICATION.md §1), tolerance 1%";
  EXPECT_LT(worst_hoop, 0.01) << "closed cylinder N_theta = pR (VERIFICATION.md §1), tolerance 1%";
}

TEST(MembranesOfRevolution, ClosedCylinderIsotropicGrowth) {
  // w = pR²(1 − ν/2)/(Et) (VERIFICATION.md §1), tolerance 1% (the faces' radii differ by 0.1%).
  const Inflated r = inflate_cylinder(isotropic_faces());
  const double exact = kPressure * kRadius * kRadius * (1 - 0.3 / 2) / 2000.0;
  double worst = 0, sample = 0;
  for (int p = 0; p < r.mesh.pair_count(); ++p) {
    const Eigen::Vector3d x = r.mesh.inner_nodes[p];
    const Eigen::Vector3d radial = Eigen::Vector3d(0, x.y(), x.z()).normalized();
    const double w = mid_displacement(r.u, p).dot(radial);
    worst = std::max(worst, relative_error(w, exact));
    if (p == r.mesh.pair_index(5, 10)) sample = w;
  }
  std::printf("  cylinder, isotropic faces: w %.5f (exact %.5f), worst error %.3f%%\n", sample, exact, 100 * worst);
  EXPECT_LT(worst, 0.01) << "closed cylinder w = pR^2(1 - nu/2)/(Et) (VERIFICATION.md §1), tolerance 1%";
}

TEST(MembranesOfRevolution, SphereBand) {
  const Inflated r = inflate_sphere_band(cord_like_section());
  const ShellMesh& mesh = r.mesh;
  const double exact = kPressure * kRadius / 2;
  // Away from the loaded edge: up to latitude 50° (the nodal edge load acts along the true meridian
  // tangent, inclined by half an element angle to the last element's chord: a local disturbance).
  double worst = 0;
  for (int j = 0; j < mesh.v_elements(); ++j)
    for (int i = 0; i < 20; ++i) {
      const Eigen::Vector2d n = face_sum(mesh, r.sections, r.u, mesh.element_index(i, j));
      worst = std::max({worst, relative_error(n[0], exact), relative_error(n[1], exact)});
    }
  const Eigen::Vector2d mid = face_sum(mesh, r.sections, r.u, mesh.element_index(6, 9));
  std::printf("  sphere R=100: N_phi %.4f, N_theta %.4f (exact %.4f); worst error %.3f%%\n", mid[0], mid[1],
              exact, 100 * worst);
  EXPECT_LT(worst, 0.01) << "sphere N = pR/2 (VERIFICATION.md §1), tolerance 1%";
}

TEST(MembranesOfRevolution, SphereIsotropicGrowth) {
  // w = pR²(1 − ν)/(2Et) (VERIFICATION.md §1), tolerance 1%, up to latitude 50°.
  const Inflated r = inflate_sphere_band(isotropic_faces());
  const double exact = kPressure * kRadius * kRadius * (1 - 0.3) / (2 * 2000.0);
  double worst = 0, sample = 0;
  for (int j = 0; j < r.mesh.v_nodes(); ++j)
    for (int i = 0; i <= 20; ++i) {
      const int p = r.mesh.pair_index(i, j);
      const double w = mid_displacement(r.u, p).dot(r.mesh.inner_nodes[p].normalized());
      worst = std::max(worst, relative_error(w, exact));
      if (i == 6 && j == 9) sample = w;
    }
  std::printf("  sphere, isotropic faces: w %.5f (exact %.5f), worst error %.3f%%\n", sample, exact, 100 * worst);
  EXPECT_LT(worst, 0.01) << "sphere w = pR^2(1 - nu)/(2Et) (VERIFICATION.md §1), tolerance 1%";
}

TEST(MembranesOfRevolution, Torus) {
  // Half torus x ≥ 0 (the meridian from the outer equator over the crown to the inner equator, both
  // ends on the symmetry plane x = 0), quarter in φ; 48 × 72 elements (3.75° × 1.25°).
  const double a = 60.0, b = 230.0;
  const ShellMesh mesh = revolution_mesh(torus_meridian(a, b), uniform_values(0, a * kPi, 48),
                                         uniform_values(0, kPi / 2, 72), false, 0.0, kCoreThickness);
  const std::vector<ElementSection> sections(mesh.element_count(), cord_like_section());
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0}));
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_max), {0}));
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::v_min), {1}));
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::v_max), {2}));
  const Eigen::VectorXd u = solve_inflation(mesh, sections, dofs, Eigen::VectorXd());

  const double n_theta = kPressure * a / 2;
  auto n_phi = [&](double r0) { return kPressure * a * (r0 + b) / (2 * r0); };
  ASSERT_NEAR(n_phi(b + a), 10.76, 0.005);
  ASSERT_NEAR(n_phi(b), 12.00, 0.005);
  ASSERT_NEAR(n_phi(b - a), 14.12, 0.005);
  double worst_phi = 0, worst_theta = 0;
  for (int j = 0; j < mesh.v_elements(); ++j)
    for (int i = 0; i < mesh.u_elements(); ++i) {
      const double s = 0.5 * (mesh.u_values[i] + mesh.u_values[i + 1]);
      const double r0 = b + a * std::cos(s / a);
      const Eigen::Vector2d n = face_sum(mesh, sections, u, mesh.element_index(i, j));
      worst_phi = std::max(worst_phi, relative_error(n[0], n_phi(r0)));
      worst_theta = std::max(worst_theta, relative_error(n[1], n_theta));
    }
  for (int i : {0, 23, 24, 47}) {
    const double s = 0.5 * (mesh.u_values[i] + mesh.u_values[i + 1]);
    const double r0 = b + a * std::cos(s / a);
    const Eigen::Vector2d n = face_sum(mesh, sections, u, mesh.element_index(i, 36));
    std::printf("  torus element %2d (r0 = %.2f): N_phi %.4f (exact %.4f), N_theta %.4f (exact %.4f)\n", i, r0,
                n[0], n_phi(r0), n[1], n_theta);
  }
  std::printf("  torus worst errors: N_phi %.3f%%, N_theta %.3f%%\n", 100 * worst_phi, 100 * worst_theta);
  EXPECT_LT(worst_phi, 0.01) << "torus N_phi = pa(r0 + b)/(2 r0) (VERIFICATION.md §1), tolerance 1%";
  EXPECT_LT(worst_theta, 0.01) << "torus N_theta = pa/2 (VERIFICATION.md §1), tolerance 1%";
}

}  // namespace
}  // namespace tirefem::verification
