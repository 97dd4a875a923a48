// Every form with a potential (MODEL.md §8) gives an energy whose derivative is its residual: central
// differences of Π along a random direction v against v·R(u), at a deformed state. The inflated tyre
// (shell + follower pressure on the closed carcass + Winkler tread on the plane) as a whole, and each
// test form on its own. Friction has no potential and says so.
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "form_fd_support.hpp"
#include "tirefem/forms/end_moment_form.hpp"
#include "tirefem/forms/linearized_form.hpp"
#include "tirefem/forms/nodal_load_form.hpp"
#include "tirefem/forms/tread_friction_form.hpp"

namespace tirefem::verification {
namespace {

TEST(FormEnergy, InflatedTyreInContactIsTheGradientOfItsEnergy) {
  // Shell + pressure (closed by rim and symmetry plane: its energy is −p V) + contact, at the inflated
  // state pressed 12 mm onto the plane (a deformed state, many points in contact), single-loop region.
  TyrePressedOntoPlane pressed;
  ManualContactRun& run = pressed.run;
  const TyreMesh& tm = pressed.tm;
  const Eigen::VectorXd& u = pressed.inflated();
  ASSERT_TRUE(run.problem->has_potential());
  int in_contact = 0;
  for (const TreadPointState& s : run.contact->evaluate(u)) in_contact += s.penetration > 0;
  EXPECT_GT(in_contact, 20);
  const Eigen::VectorXd v = random_vector(run.problem->dofs().equation_count(), 7, 1.0);
  EXPECT_LT(energy_gradient_error(*run.problem, u, v, 1.0, 1e-4), 1e-6);
  // The pressure alone (the enclosed volume's derivative is the follower load on the closed surface).
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, 0.2, Kinematics::nonlinear, true));
  NonlinearProblem pressure(dofs, std::move(forms));
  EXPECT_LT(energy_gradient_error(pressure, u, v, 0.7, 1e-4), 1e-6);
}

TEST(FormEnergy, PressureOnTheClosedCarcassIsTheGradientOfMinusPV) {
  // At a random state of the uninflated tyre: −p V has the follower load as its gradient and the
  // symmetrised load stiffness as its Hessian (the carcass is closed by the rim and the symmetry plane).
  const Case& c = example_case();
  const TyreMesh tm = build_tyre_mesh(c.tyre, coarse_mesh(16, 6));
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, 0.2, Kinematics::nonlinear, true));
  NonlinearProblem pressure(dofs, std::move(forms));
  Eigen::VectorXd u = Eigen::VectorXd::Zero(tm.mesh.dof_count());
  dofs.scatter_add(random_vector(dofs.equation_count(), 4, 2.0), u);
  const Eigen::VectorXd v = random_vector(dofs.equation_count(), 8, 1.0);
  EXPECT_LT(energy_gradient_error(pressure, u, v, 1.0, 1e-4), 1e-6);
  pressure.evaluate(u, 1.0, true);
  const Eigen::VectorXd kv = pressure.system().tangent() * v;
  const double h = 1e-5;
  Eigen::VectorXd up = u, um = u;
  dofs.scatter_add(h * v, up);
  dofs.scatter_add(-h * v, um);
  pressure.evaluate(up, 1.0, false);
  const Eigen::VectorXd rp = dofs.gather(pressure.system().residual());
  pressure.evaluate(um, 1.0, false);
  const Eigen::VectorXd fd = (rp - dofs.gather(pressure.system().residual())) / (2 * h);
  const double error = (fd - kv).norm() / kv.norm();
  std::printf("  symmetrised load stiffness against differences of the load: %.2e\n", error);
  EXPECT_LT(error, 1e-6);
}

TEST(FormEnergy, TestFormsAreTheGradientOfTheirEnergy) {
  SingleThread one_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  const int n = mesh.dof_count();
  const Eigen::VectorXd u = random_vector(n, 3, 0.5);
  const Eigen::VectorXd v = random_vector(n, 11, 1.0);
  {  // a dead load
    SingleFormProblem<NodalLoadForm> p(mesh, std::make_unique<NodalLoadForm>(random_vector(n, 5, 10.0)));
    EXPECT_LT(energy_gradient_error(*p.problem, u, v, 0.6, 1e-3), 1e-9);
  }
  {  // an end moment on a row of node pairs (directors normal to the axis x)
    std::vector<int> pairs;
    for (int p = 0; p < 7; ++p) pairs.push_back(p);
    SingleFormProblem<EndMomentForm> p(
        mesh, std::make_unique<EndMomentForm>(mesh, pairs, std::vector<double>(pairs.size(), 30.0),
                                              Eigen::Vector3d(1, 0, 0)));
    Eigen::VectorXd in_plane = v;  // keep the directors normal to the axis: no x motion
    for (int k = 0; k < n; k += 3) in_plane[k] = 0.0;
    Eigen::VectorXd at = u;
    for (int k = 0; k < n; k += 3) at[k] = 0.0;
    EXPECT_LT(energy_gradient_error(*p.problem, at, in_plane, 0.8, 1e-5), 1e-6);
  }
  {  // the Winkler tread on the drum, region frozen with points of both signs of g
    const auto support = make_support(drum_support(1000.0));
    SingleFormProblem<WinklerContactForm> p(
        mesh, std::make_unique<WinklerContactForm>(mesh, patch_points(mesh), 8.0, *support));
    p.form->set_deflection(4.0);
    std::vector<char> region = p.form->region(u);
    for (std::size_t q = 0; q < region.size(); q += 5) region[q] = 1;
    p.form->freeze_region(region);
    EXPECT_LT(energy_gradient_error(*p.problem, u, v, 1.0, 1e-5), 1e-6);
  }
}

TEST(FormEnergy, LinearizedTyreIsTheGradientOfItsQuadraticEnergy) {
  const Case& c = example_case();
  const TyreMesh tm = build_tyre_mesh(c.tyre, coarse_mesh(12, 6));
  const InflationResult inflated = run_inflation(tm, c.inflation);
  ASSERT_TRUE(inflated.converged);
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(tm.mesh, tm.sections, Kinematics::nonlinear));
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, c.inflation.pressure,
                                                 Kinematics::nonlinear, true));
  NonlinearProblem tyre(dofs, std::move(forms));
  tyre.evaluate(inflated.displacement, 1.0, true);
  std::vector<std::unique_ptr<Form>> linear;
  linear.push_back(std::make_unique<LinearizedForm>(dofs, tyre.system().tangent(), tyre.system().residual(),
                                                    inflated.displacement));
  NonlinearProblem p(dofs, std::move(linear));
  Eigen::VectorXd u = inflated.displacement;
  dofs.scatter_add(random_vector(dofs.equation_count(), 2, 0.3), u);
  EXPECT_LT(energy_gradient_error(p, u, random_vector(dofs.equation_count(), 9, 1.0), 1.0, 1e-3), 1e-8);
}

TEST(FormEnergy, FrictionHasNoPotential) {
  const ShellMesh mesh = tyre_patch_mesh();
  const auto support = make_support(plane_support());
  const std::vector<TreadPoint> points = patch_points(mesh);
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<TreadFrictionForm>(mesh, points, 8.0, 0.6, *support, -1,
                                                      std::vector<char>(points.size(), 1)));
  EXPECT_FALSE(forms.front()->has_potential());
  EXPECT_FALSE(forms.front()->energy_change(Eigen::VectorXd::Zero(mesh.dof_count()),
                                            Eigen::VectorXd::Zero(mesh.dof_count()), 1.0));
  NonlinearProblem rolling(DofMap(mesh.dof_count()), std::move(forms));
  EXPECT_FALSE(rolling.has_potential());
}

}  // namespace
}  // namespace tirefem::verification
