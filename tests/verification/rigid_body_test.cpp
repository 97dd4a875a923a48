// Rigid-body motions and the constant-strain patch test.
// References: objectivity of the Green–Lagrange strain (a rigid motion x = Q X + c leaves E = 0 and the
// internal force zero, exactly in exact arithmetic: tolerance 1e-10 relative to the force of a unit
// strain, round-off of a few hundred operations on O(1) numbers); the patch test of MacNeal & Harder
// (1985, 5-element patch, rectangle 0.24 × 0.12) with a linear displacement field on the boundary:
// a bilinear membrane reproduces a constant strain exactly (tolerance 1e-8, round-off of the solve).
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "verification_support.hpp"
#include "../element_test_section.hpp"

namespace tirefem::verification {
namespace {

struct RigidMotion {
  const char* name;
  Eigen::Matrix3d rotation;
  Eigen::Vector3d translation;
};

std::vector<RigidMotion> rigid_motions() {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized();
  const double angle = 2.0 + uniform(rng);  // a finite rotation of 1 to 3 rad
  return {
      {"translation", Eigen::Matrix3d::Identity(), Eigen::Vector3d(3.0, -7.0, 11.0)},
      {"90 deg about z", Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
       Eigen::Vector3d(1.0, 2.0, -3.0)},
      {"90 deg about x", Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix(),
       Eigen::Vector3d::Zero()},
      {"random finite rotation", Eigen::AngleAxisd(angle, axis).toRotationMatrix(),
       Eigen::Vector3d(-5.0, 0.5, 2.0)},
  };
}

NodeMatrix moved(const NodeMatrix& x, const RigidMotion& m) {
  NodeMatrix y = m.rotation * x;
  y.colwise() += m.translation;
  return y;
}

// Force of a unit strain: the linear-theory force of u = X − X̄ (E_ij = δ_ij).
double unit_strain_force(const NodeMatrix& x, const ElementSection& s) {
  const Eigen::Vector3d centre = x.rowwise().mean();
  NodeMatrix y = x + (x.colwise() - centre);
  return three_layer_element(x, y, s, Kinematics::linear, false).force.norm();
}

double max_abs_strain(const ElementPointState& st) {
  return std::max({st.inner_strain.cwiseAbs().maxCoeff(), st.outer_strain.cwiseAbs().maxCoeff(),
                   st.core_shear.cwiseAbs().maxCoeff(), std::abs(st.core_normal_strain)});
}

TEST(RigidBody, CurvedElementHasNoStrainAndNoForce) {
  const NodeMatrix x0 = curved_element();
  double worst_force = 0.0, worst_strain = 0.0;
  for (const ElementSection& s : {anisotropic_test_section(),
                                  emulated_section({2.0e5, 0.3, 4.0})}) {
    const double f_ref = unit_strain_force(x0, s);
    ASSERT_GT(f_ref, 0.0);
    for (const RigidMotion& m : rigid_motions()) {
      const NodeMatrix x = moved(x0, m);
      const ElementResponse r = three_layer_element(x0, x, s, Kinematics::nonlinear);
      worst_force = std::max(worst_force, r.force.norm() / f_ref);
      EXPECT_LT(r.force.norm() / f_ref, 1e-10)
          << m.name << ": rigid motion must give zero internal force (objectivity, tol 1e-10)";
      for (double xi : {-1.0, -0.3, 0.0, 0.577, 1.0})
        for (double eta : {-1.0, 0.2, 1.0}) {
          const ElementPointState st = three_layer_point_state(x0, x, s, Kinematics::nonlinear, xi, eta);
          worst_strain = std::max(worst_strain, max_abs_strain(st));
          EXPECT_LT(max_abs_strain(st), 1e-12)
              << m.name << " at (" << xi << ", " << eta << "): rigid motion must give zero strain";
        }
      // A rigid motion superposed on a deformed state leaves the strain energy unchanged.
      NodeMatrix deformed = x0;
      deformed(0, 2) += 0.3;
      deformed(2, 5) -= 0.2;
      deformed(1, 7) += 0.1;
      const double e0 = three_layer_element(x0, deformed, s, Kinematics::nonlinear, false).energy;
      const double e1 = three_layer_element(x0, moved(deformed, m), s, Kinematics::nonlinear, false).energy;
      EXPECT_NEAR(e1, e0, 1e-12 * e0) << m.name << ": energy must be invariant under rigid motion";
    }
  }
  std::printf("  curved element, rigid motions: max |f|/f_unit %.2e, max |strain| %.2e\n", worst_force, worst_strain);
}

TEST(RigidBody, LinearTheoryTranslationAndInfinitesimalRotation) {
  // The linear theory is invariant under translations and infinitesimal rotations u = ω × X only.
  const NodeMatrix x0 = curved_element();
  const ElementSection s = anisotropic_test_section();
  const double f_ref = unit_strain_force(x0, s);
  NodeMatrix x = x0;
  const Eigen::Vector3d omega(0.3, -0.2, 0.5), c(1, 2, 3);
  for (int k = 0; k < kElementNodes; ++k) x.col(k) += omega.cross(x0.col(k)) + c;
  const ElementResponse r = three_layer_element(x0, x, s, Kinematics::linear, false);
  EXPECT_LT(r.force.norm() / f_ref, 1e-10) << "linear theory: infinitesimal rigid motion, tol 1e-10";
}

// A small curved mesh: a patch of a torus with unequal element sizes, tyre-like faces.
TEST(RigidBody, CurvedMeshHasNoResidual) {
  const ShellMesh mesh = revolution_mesh(torus_meridian(60.0, 230.0), {0.0, 9.0, 25.0, 31.0},
                                         {-0.2, -0.13, 0.05, 0.11}, false, -2.0, 3.0);
  const std::vector<ElementSection> sections(mesh.element_count(), anisotropic_test_section());
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::nonlinear));
  NonlinearProblem problem(DofMap(mesh.dof_count()), std::move(forms));

  // Reference: linear-theory force of a unit strain, assembled over the mesh.
  double f_ref = 0.0;
  {
    std::vector<std::unique_ptr<Form>> lin;
    lin.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::linear));
    NonlinearProblem linear(DofMap(mesh.dof_count()), std::move(lin));
    Eigen::VectorXd u(mesh.dof_count());
    for (int p = 0; p < mesh.pair_count(); ++p)
      for (int c = 0; c < 3; ++c) {
        u[inner_dof(p, c)] = mesh.inner_nodes[p][c];
        u[outer_dof(p, c)] = mesh.outer_nodes[p][c];
      }
    linear.evaluate(u, 1.0, false);
    f_ref = linear.system().residual().norm();
  }
  ASSERT_GT(f_ref, 0.0);

  for (const RigidMotion& m : rigid_motions()) {
    Eigen::VectorXd u(mesh.dof_count());
    for (int p = 0; p < mesh.pair_count(); ++p) {
      const Eigen::Vector3d di = m.rotation * mesh.inner_nodes[p] + m.translation - mesh.inner_nodes[p];
      const Eigen::Vector3d dout = m.rotation * mesh.outer_nodes[p] + m.translation - mesh.outer_nodes[p];
      for (int c = 0; c < 3; ++c) {
        u[inner_dof(p, c)] = di[c];
        u[outer_dof(p, c)] = dout[c];
      }
    }
    problem.evaluate(u, 1.0, false);
    EXPECT_LT(problem.system().residual().norm() / f_ref, 1e-10)
        << m.name << ": mesh internal force under rigid motion (tol 1e-10 of a unit-strain force)";
    double worst = 0.0;
    for (int e = 0; e < mesh.element_count(); ++e)
      for (const auto& gp : kGauss2x2)
        worst = std::max(worst, max_abs_strain(three_layer_point_state(
                                    mesh.element_reference(e), element_current(mesh, e, u),
                                    sections[e], Kinematics::nonlinear, gp[0], gp[1])));
    EXPECT_LT(worst, 1e-12) << m.name << ": strain in the mesh under rigid motion";
  }
}

// ---- constant-strain patch test (MacNeal & Harder 1985) --------------------------------------------
ShellMesh macneal_harder_patch(double thickness) {
  const std::vector<Eigen::Vector2d> xy{{0, 0},       {0.24, 0},    {0.24, 0.12}, {0, 0.12},
                                        {0.04, 0.02}, {0.18, 0.03}, {0.16, 0.08}, {0.08, 0.08}};
  ShellMesh mesh;
  for (const auto& p : xy) {
    mesh.inner_nodes.emplace_back(p.x(), p.y(), -0.5 * thickness);
    mesh.outer_nodes.emplace_back(p.x(), p.y(), 0.5 * thickness);
  }
  mesh.elements = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  return mesh;
}

void run_patch_test(Kinematics kinematics) {
  const ShellMesh mesh = macneal_harder_patch(0.01);
  ElementSection section;
  section.inner_face = isotropic_membrane(1.0e6, 0.25, 0.001);
  // Isotropic faces (different on purpose): an anisotropic A is given in each element's own frame
  // (axis 1 along its ξ direction), so on this distorted patch it would be a different material in
  // each element and a uniform strain would not be an equilibrium state.
  section.outer_face = isotropic_membrane(3.0e5, 0.4, 0.002);
  section.core_shear_modulus = 500.0;
  section.core_normal_modulus = 1.0e4;
  const std::vector<ElementSection> sections(mesh.element_count(), section);

  // Displacement gradient of the in-plane field u = H X (finite, so the nonlinear strain is tested).
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  h.topLeftCorner<2, 2>() << 0.10, 0.05, -0.03, 0.08;
  const Eigen::Matrix3d f = Eigen::Matrix3d::Identity() + h;
  const Eigen::Matrix3d strain = kinematics == Kinematics::nonlinear
                                     ? Eigen::Matrix3d(0.5 * (f.transpose() * f - Eigen::Matrix3d::Identity()))
                                     : Eigen::Matrix3d(0.5 * (h + h.transpose()));

  DofMap dofs(mesh.dof_count());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int p = 0; p < 4; ++p) {  // the boundary nodes: prescribed on both faces, all components
    dofs.fix(both_faces({p}, {0, 1, 2}));
    const Eigen::Vector3d ui = h * mesh.inner_nodes[p], uo = h * mesh.outer_nodes[p];
    for (int c = 0; c < 3; ++c) {
      u[inner_dof(p, c)] = ui[c];
      u[outer_dof(p, c)] = uo[c];
    }
  }
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, kinematics));
  NonlinearProblem problem(dofs, std::move(forms));
  const double force_scale = section.inner_face.norm() * strain.norm() * 0.24;
  solve_prescribed(problem, u, force_scale);

  // Interior nodes follow the linear field.
  for (int p = 4; p < 8; ++p) {
    const Eigen::Vector3d exact = h * mesh.inner_nodes[p];
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(u[inner_dof(p, c)], exact[c], 1e-8 * h.norm() * 0.24)
          << "patch test: interior node " << p << " component " << c << " (tol 1e-8)";
      EXPECT_NEAR(u[outer_dof(p, c)], exact[c], 1e-8 * h.norm() * 0.24);
    }
  }
  // Uniform strain at every Gauss point and the centre of every element, in the local frame.
  for (int e = 0; e < mesh.element_count(); ++e) {
    const auto x0 = mesh.element_reference(e);
    const auto x = element_current(mesh, e, u);
    const std::array<std::array<double, 2>, 6> points{
        {{0.0, 0.0}, kGauss2x2[0], kGauss2x2[1], kGauss2x2[2], kGauss2x2[3], {1.0, -1.0}}};
    for (const auto& pt : points) {
      const ElementPointState st = three_layer_point_state(x0, x, section, kinematics, pt[0], pt[1]);
      const Eigen::Vector3d& e1 = st.inner_axis1;
      const Eigen::Vector3d& e2 = st.inner_axis2;
      const Eigen::Vector3d exact(e1.dot(strain * e1), e2.dot(strain * e2), 2 * e1.dot(strain * e2));
      EXPECT_LT((st.inner_strain - exact).norm(), 1e-8 * strain.norm())
          << "patch test: inner face strain, element " << e << " (MacNeal–Harder, tol 1e-8)";
      EXPECT_LT((st.outer_strain - exact).norm(), 1e-8 * strain.norm())
          << "patch test: outer face strain, element " << e;
      EXPECT_LT(st.core_shear.norm() + std::abs(st.core_normal_strain), 1e-8 * strain.norm())
          << "patch test: the interlayer is not strained by an in-plane field, element " << e;
      EXPECT_LT((st.inner_resultant - section.inner_face * exact).norm(),
                1e-8 * section.inner_face.norm() * strain.norm());
    }
  }
}

TEST(PatchTest, ConstantMembraneStrainNonlinear) { run_patch_test(Kinematics::nonlinear); }
TEST(PatchTest, ConstantMembraneStrainLinear) { run_patch_test(Kinematics::linear); }

}  // namespace
}  // namespace tirefem::verification
