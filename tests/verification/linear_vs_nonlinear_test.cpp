// The geometrically linear theory is the first-order part of the nonlinear one: at a load factor λ
// (λ = 1 a load that deforms the structure visibly nonlinearly) the relative difference
// ‖u_nl − u_lin‖ / ‖u_lin‖ is O(λ). Reference: Taylor expansion of the equilibrium equations. Checked
// as (a) the difference divided by λ is the same constant, within 10%, over λ = 1e-2, 1e-3, 1e-4
// (a first-order term; higher-order terms change it by O(λ)), and (b) that constant is O(1) (between
// 0.01 and 10): the load factor measures the nonlinearity.
#include <cstdio>

#include <gtest/gtest.h>

#include "tirefem/forms/nodal_load_form.hpp"
#include "tirefem/forms/pressure_form.hpp"
#include "verification_support.hpp"

namespace tirefem::verification {
namespace {

using ProblemFactory = std::function<std::unique_ptr<NonlinearProblem>(Kinematics)>;

// Relative differences at the given load factors.
std::vector<double> relative_differences(const ProblemFactory& make, const std::vector<double>& factors) {
  const auto linear = make(Kinematics::linear);
  const Eigen::VectorXd u_lin = solve_linear(*linear, 1e-6);  // at λ = 1; the linear answer scales
  const auto nonlinear = make(Kinematics::nonlinear);
  std::vector<double> out;
  for (double lambda : factors) {
    // The residual's round-off floor is absolute (positions X + u carry ε|X|): up to ~1e-9 of the
    // full load here, i.e. 1e-9/λ relative to λF. Ask for 1e-8 of the full load.
    NewtonSettings settings;
    settings.residual_tolerance = 1e-8 / lambda;
    NewtonSolver newton(*nonlinear, settings);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(u_lin.size());
    const NewtonOutcome o = newton.solve(u, lambda);
    EXPECT_TRUE(o.converged) << "nonlinear solve at load factor " << lambda;
    out.push_back((u - lambda * u_lin).norm() / (lambda * u_lin.norm()));
  }
  return out;
}

void expect_first_order(const char* label, const std::vector<double>& factors, const std::vector<double>& diff) {
  for (size_t k = 0; k < factors.size(); ++k)
    std::printf("  %s: load factor %.0e, relative difference %.4e, difference / load factor %.4f\n", label,
                factors[k], diff[k], diff[k] / factors[k]);
  const double c = diff.back() / factors.back();
  EXPECT_GT(c, 0.01) << label << ": the nonlinear correction per unit load factor must be O(1)";
  EXPECT_LT(c, 10.0) << label << ": the nonlinear correction per unit load factor must be O(1)";
  for (size_t k = 0; k + 1 < factors.size(); ++k)
    EXPECT_NEAR(diff[k] / factors[k], c, 0.1 * c)
        << label << ": relative difference must be proportional to the load factor (first order), tol 10%";
}

TEST(LinearVsNonlinear, PanelUnderFollowerPressure) {
  // The cantilevered cylindrical panel of the equilibrium test (p = 0.02 lifts its tip by 5% of its
  // length at λ = 1): follower pressure against dead pressure on the reference geometry.
  const ShellMesh mesh = cylinder_segment_mesh(250.0, uniform_values(0, 100, 10),
                                               uniform_values(degrees(-20), degrees(20), 8), 0.0, 6.0);
  ElementSection s;
  s.inner_face << 1200, 250, 0, 250, 400, 0, 0, 0, 80;
  s.outer_face << 4000, 2200, 0, 2200, 2500, 0, 0, 0, 2300;
  s.core_shear_modulus = 1.0;
  s.core_normal_modulus = 20.0;
  const std::vector<ElementSection> sections(mesh.element_count(), s);
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0, 1, 2}));
  const ProblemFactory make = [&](Kinematics k) {
    std::vector<std::unique_ptr<Form>> forms;
    forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, k));
    forms.push_back(std::make_unique<PressureForm>(mesh, all_elements(mesh), 0.02, k, false));
    return std::make_unique<NonlinearProblem>(dofs, std::move(forms));
  };
  const std::vector<double> factors{1e-2, 1e-3, 1e-4};
  expect_first_order("panel, follower pressure", factors, relative_differences(make, factors));
}

TEST(LinearVsNonlinear, CantileverUnderEndShear) {
  // Sze's cantilever (VERIFICATION.md §3) emulated as an isotropic shell; λ = 1 is P = 4 (tip rotation
  // about 70°). The difference is first order through the axial shortening u ~ w²/L.
  const IsotropicShell shell{1.2e6, 0.0, 0.1};
  const double d = face_distance(shell);
  const ShellMesh mesh = plate_mesh(10.0, 1.0, 16, 1, -d / 2, d / 2);
  const std::vector<ElementSection> sections(mesh.element_count(), emulated_section(shell));
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0, 1, 2}));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int p : mesh.edge_pairs(GridEdge::u_max)) add_split_force(f, p, Eigen::Vector3d(0, 0, 2.0));
  const ProblemFactory make = [&](Kinematics k) {
    std::vector<std::unique_ptr<Form>> forms;
    forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, k));
    forms.push_back(std::make_unique<NodalLoadForm>(f));
    return std::make_unique<NonlinearProblem>(dofs, std::move(forms));
  };
  const std::vector<double> factors{1e-2, 1e-3, 1e-4};
  expect_first_order("cantilever, end shear", factors, relative_differences(make, factors));
}

}  // namespace
}  // namespace tirefem::verification
