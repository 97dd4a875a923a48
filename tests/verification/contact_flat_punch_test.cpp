// A flat rigid punch on a Winkler layer (VERIFICATION.md §4: "stiff shell pressed on a Winkler layer by a
// uniform δ: Qz = kp A δ").
//
// (a) Held punch: a flat plate (120 × 80 mm, graded 6 × 4 mesh) whose flat tread surface (hp = 8 mm
//     below the breaker face) lies exactly at z = 0, every DOF fixed, the road plane moved up by δ.
//     Every tread point penetrates by exactly δ, so patch_figures must give Qz = kp A δ, contact area = A,
//     mean = max pressure = kp δ. The Gauss weights sum to the element areas exactly (bilinear map of a
//     rectangle), so the only error is round-off: tolerance 1e-10 relative.
// (b) Free plate under a uniform dead pressure q on its inner face, in-plane DOFs held, solved with the
//     two-level contact iteration: a uniform load on a uniform Winkler layer settles the plate without
//     bending whatever its stiffness (the consistent nodal loads of the pressure and of the tread are both
//     those of a constant on the same rectangles), so the tread pressure is q everywhere: Qz = q A and
//     g = q / kp at every tread point. Tolerance 1e-10 relative: Newton is driven to 1e-12 of the load.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "tirefem/forms/nodal_load_form.hpp"

namespace tirefem::verification {
namespace {

constexpr double kLx = 120.0, kLy = 80.0, kTreadHeight = 8.0, kCore = 3.0;

// Plate over [−60, 60] × [−40, 40], breaker (outer) face at z = hp, carcass (inner) face 3 mm above it;
// the face normal (inner → outer) points down, so the tread surface hp below the breaker is z = 0.
ShellMesh punch_mesh() {
  return build_grid_mesh(graded_values(-0.5 * kLx, 0.5 * kLx, 6, 1.8), graded_values(-0.5 * kLy, 0.5 * kLy, 4, 0.6),
                         false, [](double x, double y) {
                           return NodePairPosition{Eigen::Vector3d(x, y, kTreadHeight + kCore),
                                                   Eigen::Vector3d(x, y, kTreadHeight)};
                         });
}

std::vector<TreadPoint> punch_points(const ShellMesh& mesh) {
  return make_tread_points(mesh, all_elements(mesh), 4, [](double) { return kTreadHeight; });
}

TEST(ContactFlatPunch, HeldPunchCarriesKpAreaDeflection) {
  const ShellMesh mesh = punch_mesh();
  const std::vector<TreadPoint> points = punch_points(mesh);
  for (const TreadPoint& p : points) ASSERT_NEAR(p.reference.z(), 0.0, 1e-12) << "tread surface must be z = 0";
  RoadPlane plane;
  const double kp = 1.0, area = kLx * kLy;
  WinklerContactForm contact(mesh, points, kp, plane);
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());  // every DOF held at zero
  for (double delta : {0.5, 2.5, 7.0}) {
    contact.set_deflection(delta);
    const PatchFigures f = patch_figures(points, contact.evaluate(u), /*half_model=*/false);
    const double expected = kp * area * delta;
    std::printf("  held punch, δ %.1f mm: Qz %.10g N (kp A δ = %.10g, relative error %.1e), area %.10g mm² "
                "(A = %.10g, relative error %.1e), mean pressure %.6g MPa\n",
                delta, f.Qz_N, expected, std::abs(f.Qz_N - expected) / expected, f.contact_area_mm2, area,
                std::abs(f.contact_area_mm2 - area) / area, f.mean_pressure_MPa);
    EXPECT_NEAR(f.Qz_N, expected, 1e-10 * expected) << "Qz = kp A δ (VERIFICATION.md §4)";
    EXPECT_NEAR(f.contact_area_mm2, area, 1e-10 * area) << "the whole plate is in contact";
    EXPECT_NEAR(f.mean_pressure_MPa, kp * delta, 1e-10 * kp * delta);
    EXPECT_NEAR(f.max_pressure_MPa, kp * delta, 1e-10 * kp * delta);
    EXPECT_NEAR(f.force_N.head<2>().norm(), 0.0, 1e-10 * expected) << "a plane pushes straight up";
  }
}

TEST(ContactFlatPunch, FreePlateUnderUniformPressureSettlesUniformly) {
  const ShellMesh mesh = punch_mesh();
  const std::vector<TreadPoint> points = punch_points(mesh);
  const double kp = 0.8, q = 0.2, delta = 1.5, area = kLx * kLy;
  ElementSection section;  // a belt-like stiff plate
  section.inner_face = isotropic_membrane(5000.0, 0.3, 1.0);
  section.outer_face = isotropic_membrane(20000.0, 0.3, 1.0);
  section.core_shear_modulus = 2.0;
  section.core_normal_modulus = 50.0;
  const std::vector<ElementSection> sections(mesh.element_count(), section);

  RoadPlane plane;
  DofMap dofs(mesh.dof_count());
  std::vector<int> all_pairs(mesh.pair_count());
  for (int p = 0; p < mesh.pair_count(); ++p) all_pairs[p] = p;
  dofs.fix(both_faces(all_pairs, {0, 1}));  // in-plane rigid motions (and nothing else of consequence)
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::nonlinear));
  forms.push_back(std::make_unique<NodalLoadForm>(
      surface_load_vector(mesh, all_elements(mesh), Face::inner, Eigen::Vector3d(0, 0, -q))));
  auto c = std::make_unique<WinklerContactForm>(mesh, points, kp, plane);
  WinklerContactForm& contact = *c;
  forms.push_back(std::move(c));
  NonlinearProblem problem(dofs, std::move(forms));
  NewtonSettings ns;
  ns.residual_tolerance = 1e-12;
  NewtonSolver newton(problem, ns);
  ContactSettings settings = test_contact_settings();
  settings.residual_tolerance = 1e-12;

  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
  contact.set_deflection(delta);
  const ContactSolveOutcome out = solve_contact(newton, contact, u, settings);
  ASSERT_TRUE(out.converged) << out.failure;
  const std::vector<TreadPointState> states = contact.evaluate(u);
  const PatchFigures f = patch_figures(points, states, false);
  double worst_g = 0.0;
  for (const TreadPointState& s : states) worst_g = std::max(worst_g, std::abs(s.penetration - q / kp));
  std::printf("  free plate, q %.2f MPa on kp %.2f: Qz %.10g N (q A = %.10g, relative error %.1e), max |g − q/kp| "
              "%.2e mm, %d contact / %d Newton iterations\n",
              q, kp, f.Qz_N, q * area, std::abs(f.Qz_N - q * area) / (q * area), worst_g, out.contact_iterations,
              out.newton_iterations);
  EXPECT_NEAR(f.Qz_N, q * area, 1e-10 * q * area) << "the tread carries the uniform load: Qz = q A";
  EXPECT_NEAR(f.contact_area_mm2, area, 1e-10 * area);
  EXPECT_LT(worst_g, 1e-10 * q / kp) << "uniform settlement: g = q / kp at every tread point";
}

}  // namespace
}  // namespace tirefem::verification
