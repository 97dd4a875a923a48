// The standing tyre's tangential stiffness (analysis/standing_stiffness.hpp) and the glued tread behind it
// (forms/stuck_tread_form.hpp).
//
// The form: its tangent against central differences of its residual and its residual against differences
// of its energy, with the road translated and turned and the normals tilted (a drum-like patch); a tyre
// that moves with the road in the road's plane, or along the normal, is not sheared.
// The analysis, on the example tyre at 2000 N (64 × 16 per half, equal elements: a stable footprint): the half model's longitudinal stiffness
// equals the full model's (the half is doubled); each stiffness is positive and below the tread's own
// Σ (G/hp) w (the carcass is in series with it); each response is the derivative of the equilibrium path:
// moving the road by ε times the motion and the tyre by ε times its response leaves the whole static
// residual (shell, pressure, Winkler tread, glued tread) at its converged value to O(ε²). The
// rigid-carcass limit is in CorneringBrush.*.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "form_fd_support.hpp"
#include "tirefem/analysis/standing_stiffness.hpp"
#include "tirefem/analysis/tyre_shell_forms.hpp"
#include "tirefem/forms/pressure_form.hpp"
#include "tirefem/forms/stuck_tread_form.hpp"

namespace tirefem::verification {
namespace {

// The patch mesh's tread points, anchored near where they stand (offsets of ±0.3 mm), the normals those
// of a drum of radius 500 mm below the patch.
std::unique_ptr<SingleFormProblem<StuckTreadForm>> stuck_form(const ShellMesh& mesh) {
  std::vector<TreadPoint> points = patch_points(mesh);
  std::vector<Eigen::Vector3d> anchors, normals;
  const Eigen::VectorXd offsets = random_vector(3 * static_cast<int>(points.size()), 21, 0.3);
  for (std::size_t q = 0; q < points.size(); ++q) {
    anchors.push_back(points[q].reference + offsets.segment<3>(3 * q));
    normals.push_back(Eigen::Vector3d(0.0, -points[q].reference.y(), 500.0).normalized());
  }
  return std::make_unique<SingleFormProblem<StuckTreadForm>>(
      mesh, std::make_unique<StuckTreadForm>(points, anchors, normals, 0.8));
}

TEST(StuckTread, TangentAndEnergyAreTheDerivativesOfItsResidual) {
  SingleThread one_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  const auto p = stuck_form(mesh);
  StuckTreadForm* form = p->form;
  RoadMotion motion;
  motion.translation = Eigen::Vector3d(0.4, -0.7, 0.2);
  motion.turn = 0.01;
  motion.centre = Eigen::Vector3d(3.0, -5.0, 0.0);
  form->set_road_motion(motion);
  const int n = mesh.dof_count();
  const Eigen::VectorXd u = random_vector(n, 5, 0.5);
  const double error = max_relative_error(fd_tangent(*p, u), p->tangent(u));
  std::printf("  glued tread: tangent against central differences %.2e\n", error);
  EXPECT_LT(error, kFdTolerance);
  EXPECT_LT(energy_gradient_error(*p->problem, u, random_vector(n, 6, 1.0), 1.0, 1e-4), 1e-7);
  // Symmetric, and the residual is the sum of the points' forces with the opposite sign.
  const Eigen::MatrixXd k = p->tangent(u);
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-14 * k.cwiseAbs().maxCoeff());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const Eigen::VectorXd r = p->residual(u);
  for (int pair = 0; pair < mesh.dof_count() / 6; ++pair) sum += r.segment<3>(outer_dof(pair, 0));
  EXPECT_LT((sum + form->resultant(u, Eigen::Vector3d::Zero()).first).norm(), 1e-10 * sum.norm());
}

TEST(StuckTread, NoShearWhenTheTyreMovesWithTheRoad) {
  const ShellMesh mesh = tyre_patch_mesh();
  std::vector<TreadPoint> points = patch_points(mesh);
  std::vector<Eigen::Vector3d> anchors, normals;
  for (const TreadPoint& p : points) anchors.push_back(p.reference), normals.push_back(Eigen::Vector3d::UnitZ());
  StuckTreadForm form(points, anchors, normals, 0.8);
  RoadMotion motion;
  motion.translation = Eigen::Vector3d(0.3, -0.2, 0.0);
  form.set_road_motion(motion);
  // Every outer face node moved as the road moves, plus any motion along the normal. (A turn is not tested
  // so: the tread's offset hp n0 does not turn with the breaker, the paper's kinematics.)
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int pair = 0; pair < mesh.dof_count() / 6; ++pair)
    u.segment<3>(outer_dof(pair, 0)) = motion.translation + 0.1 * std::sin(pair) * Eigen::Vector3d::UnitZ();
  double largest = 0.0;
  for (int q = 0; q < static_cast<int>(points.size()); ++q) largest = std::max(largest, form.point_force(q, u).norm());
  EXPECT_LT(largest, 1e-12);
  // Held still, each point carries its spring times the road's displacement in the plane.
  const Eigen::VectorXd still = Eigen::VectorXd::Zero(mesh.dof_count());
  const Eigen::Vector3d expected = form.spring(7) * form.road_displacement(7);
  EXPECT_LT((form.point_force(7, still) - expected).norm(), 1e-12 * expected.norm());
}

struct Standing {
  TyreMesh tm;
  StaticContactResult footprint;
  std::optional<StandingStiffness> stiffness;
  std::vector<Eigen::VectorXd> responses;
};

Standing standing(bool half_model) {
  const Case& c = example_case();
  Standing s{build_tyre_mesh(c.tyre, coarse_mesh(64, 16, half_model, 1.0)), {}, {}, {}};
  const TyreMesh& tm = s.tm;
  FootprintStudy fs;
  fs.name = "standing";
  fs.target_load = 2000.0;
  s.footprint = run_footprint(tm, c.tyre, c.inflation, test_contact_settings(ContactSettings::Iteration::single_loop), fs);
  EXPECT_TRUE(s.footprint.completed) << s.footprint.failure;
  if (!s.footprint.completed) return s;
  const RoadPlane plane;
  s.stiffness = standing_stiffness(tm, c.tyre, c.inflation.pressure, plane, s.footprint.final_state.deflection_mm,
                                   s.footprint.tread_points, s.footprint.final_state.displacement, &s.responses);
  return s;
}

// The static residual over the free DOFs at u with the road moved by `motion`: the tyre (shell, closed
// pressure), the Winkler tread frozen to its region at `base`, and the tread glued where it stood at `base`
// (as analysis/standing_stiffness.cpp builds it).
Eigen::VectorXd static_residual(const Standing& s, const Eigen::VectorXd& u, const RoadMotion& motion) {
  const Case& c = example_case();
  const TyreMesh& tm = s.tm;
  const Eigen::VectorXd& base = s.footprint.final_state.displacement;
  const RoadPlane plane;
  const double deflection = s.footprint.final_state.deflection_mm;
  auto winkler = std::make_unique<WinklerContactForm>(tm.mesh, s.footprint.tread_points, c.tyre.tread_stiffness, plane);
  winkler->set_deflection(deflection);
  std::vector<TreadPoint> stuck;
  std::vector<Eigen::Vector3d> anchors, normals;
  const std::vector<TreadPointState> states = winkler->evaluate(base);
  for (std::size_t q = 0; q < states.size(); ++q)
    if (states[q].penetration > 0 && winkler->points()[q].height > 0) {
      stuck.push_back(winkler->points()[q]);
      anchors.push_back(states[q].position);
      normals.push_back(Eigen::Vector3d::UnitZ());
    }
  winkler->freeze_region(winkler->region(base));
  auto glued = std::make_unique<StuckTreadForm>(stuck, anchors, normals, c.tyre.tread_shear_modulus);
  glued->set_road_motion(motion);
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  add_tyre_shell_forms(forms, tm, Kinematics::nonlinear);
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, c.inflation.pressure,
                                                 Kinematics::nonlinear, true));
  forms.push_back(std::move(winkler));
  forms.push_back(std::move(glued));
  NonlinearProblem problem(dofs, std::move(forms));
  problem.evaluate(u, 1.0, false);
  return dofs.gather(problem.system().residual());
}

TEST(StandingStiffness, HalfModelEqualsFullAndTheTreadIsInSeriesWithTheCarcass) {
  const Standing half = standing(true), full = standing(false);
  ASSERT_TRUE(half.stiffness && full.stiffness);
  const StandingStiffness& h = *half.stiffness;
  const StandingStiffness& f = *full.stiffness;
  std::printf("  64 x 16, 2000 N: Cx half %.3f / full %.3f N/mm, Cy %.3f N/mm, yaw %.1f N·m/rad; tread alone %.1f / %.1f "
              "N/mm; %d / %d points in contact\n", h.longitudinal_N_per_mm, f.longitudinal_N_per_mm,
              f.lateral_N_per_mm.value_or(0.0), f.yaw_Nmm_per_rad.value_or(0.0) * 1e-3, h.tread_shear_N_per_mm,
              f.tread_shear_N_per_mm, h.contact_points, f.contact_points);
  EXPECT_FALSE(h.lateral_N_per_mm || h.yaw_Nmm_per_rad);
  ASSERT_TRUE(f.lateral_N_per_mm && f.yaw_Nmm_per_rad);
  EXPECT_NEAR(h.longitudinal_N_per_mm, f.longitudinal_N_per_mm, 1e-4 * f.longitudinal_N_per_mm);
  EXPECT_NEAR(h.tread_shear_N_per_mm, f.tread_shear_N_per_mm, 1e-9 * f.tread_shear_N_per_mm);
  for (double c : {f.longitudinal_N_per_mm, *f.lateral_N_per_mm}) {
    EXPECT_GT(c, 0.0);
    EXPECT_LT(c, f.tread_shear_N_per_mm);
  }
  EXPECT_GT(*f.yaw_Nmm_per_rad, 0.0);
  EXPECT_EQ(f.factorizations, 1);
  EXPECT_TRUE(f.stable && h.stable);

  // The responses (full model): the road moved by ε × each motion, the tyre by ε × its response.
  ASSERT_EQ(full.responses.size(), 3u);
  const Eigen::VectorXd& base = full.footprint.final_state.displacement;
  const Eigen::VectorXd r0 = static_residual(full, base, RoadMotion{});
  RoadMotion along, across, turn;
  along.translation = Eigen::Vector3d::UnitY();
  across.translation = Eigen::Vector3d::UnitX();
  turn.turn = 1.0;
  turn.centre = f.centre_mm;
  const RoadMotion motions[3] = {along, across, turn};
  const char* names[3] = {"along", "across", "turn"};
  for (int m = 0; m < 3; ++m) {
    // ε: 0.01 and 0.001 mm of road travel (the turn: the same at 100 mm from the centre).
    double error[2];
    for (int k = 0; k < 2; ++k) {
      const double eps = (k == 0 ? 1.0 : 0.1) * (m == 2 ? 1e-4 : 1e-2);
      RoadMotion moved = motions[m];
      moved.translation *= eps;
      moved.turn *= eps;
      const Eigen::VectorXd load = r0 - static_residual(full, base, moved);  // the road's pull on the standing tyre
      error[k] = (static_residual(full, base + eps * full.responses[m], moved) - r0).norm() / load.norm();
    }
    std::printf("  road moved %s: residual left %.2e, %.2e of the load (ε, ε/10)\n", names[m], error[0], error[1]);
    EXPECT_GT(error[0] / error[1], 8.0) << names[m];  // O(ε²): ten times less for ε/10
    EXPECT_LT(error[0] / error[1], 12.0) << names[m];
    EXPECT_LT(error[1], 1e-3) << names[m];
  }
}

}  // namespace
}  // namespace tirefem::verification
