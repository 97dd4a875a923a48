// Classic shell benchmarks through the isotropic emulation (VERIFICATION.md §2, §3): faces at ±t/(2√3)
// with membrane stiffness E(t/2)/(1 − ν²) each, core shear modulus κG√3, core normal modulus E.
// Linear: Scordelis–Lo roof (0.3024) and the pinched hemisphere with an 18° hole (0.094), MacNeal &
// Harder (1985). Nonlinear: Sze, Liu & Lo (2004) cantilever under end shear (table of 5 load levels)
// and the cantilever rolled up into a full circle by an end moment (exact elastica).
// Tolerances: 3% ("a few %"): the references are themselves ~1–2% uncertain (the roof's deep-shell
// value is 0.3086, while 0.3024 is what converged shear-deformable elements give; 0.094 is quoted to two
// digits; Sze's table is an Abaqus S4R 16 × 1 solution); each assertion names its value. The roll-up
// is compared with the exact elastica to 2% of L.
#include <cstdio>

#include <gtest/gtest.h>

#include "tirefem/forms/end_moment_form.hpp"
#include "tirefem/forms/nodal_load_form.hpp"
#include "verification_support.hpp"

namespace tirefem::verification {
namespace {

// The residual of these thin, stiff shells has a round-off floor above the solver's default 1e-8 of
// the applied load: nodal positions X + u carry an absolute error ε|X|, which the membrane and
// through-thickness stiffnesses (E t / h, E / d per unit area) turn into nodal forces of 1e-7 to 1e-5
// of the load. Newton then stalls there; the displacements are converged long before (the stall is
// noise in the stiffest modes). 1e-6 / 1e-4 are above the floors seen (2e-7 nonlinear cantilever,
// 4e-5 hemisphere) and far below what would change a displacement in the reported digits.
NewtonSettings benchmark_newton_settings() {
  NewtonSettings s;
  s.residual_tolerance = 1e-6;
  return s;
}
constexpr double kLinearResidualTolerance = 1e-4;

// ---- Scordelis–Lo roof -----------------------------------------------------------------------------
// R = 25, L = 50, t = 0.25, E = 4.32e8, ν = 0, 40° half-angle, gravity 90 per unit area, rigid end
// diaphragms (u_y = u_z = 0, x free). Quarter model: x ∈ [0, 25] (x = 25 midspan symmetry),
// θ ∈ [0, 40°] from the crown (θ = 0 symmetry), free edge at θ = 40°.
double scordelis_lo(int n) {
  const IsotropicShell shell{4.32e8, 0.0, 0.25};
  const double d = face_distance(shell), radius = 25.0;
  const ShellMesh mesh = cylinder_segment_mesh(radius, uniform_values(0, 25, n),
                                               uniform_values(0, degrees(40), n), -d / 2, d / 2);
  const std::vector<ElementSection> sections(mesh.element_count(), emulated_section(shell));
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {1, 2}));  // diaphragm
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_max), {0}));     // midspan symmetry
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::v_min), {1}));     // crown symmetry
  // Gravity per unit mid-surface area, half on each face (the faces' areas average to the
  // mid-surface's on a cylinder).
  const Eigen::Vector3d half_gravity(0, 0, -45.0);
  Eigen::VectorXd f = surface_load_vector(mesh, all_elements(mesh), Face::inner, half_gravity) +
                      surface_load_vector(mesh, all_elements(mesh), Face::outer, half_gravity);
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::linear));
  forms.push_back(std::make_unique<NodalLoadForm>(f));
  NonlinearProblem problem(dofs, std::move(forms));
  const Eigen::VectorXd u = solve_linear(problem, kLinearResidualTolerance);
  return -mid_displacement(u, mesh.pair_index(n, n)).z();  // midspan of the free edge, downwards
}

TEST(ShellBenchmarks, ScordelisLoRoof) {
  constexpr double reference = 0.3024;
  const double w8 = scordelis_lo(8), w16 = scordelis_lo(16), w32 = scordelis_lo(32);
  std::printf("  Scordelis-Lo: 8x8 %.5f (%.4f), 16x16 %.5f (%.4f), 32x32 %.5f (%.4f); reference %.4f\n", w8,
              w8 / reference, w16, w16 / reference, w32, w32 / reference, reference);
  EXPECT_NEAR(w16, reference, 0.03 * reference)
      << "Scordelis-Lo roof, 16x16 quarter, linear: 0.3024 (MacNeal & Harder 1985), tolerance 3%";
  EXPECT_NEAR(w32, reference, 0.03 * reference) << "Scordelis-Lo roof, 32x32 quarter, tolerance 3%";
  EXPECT_LT(std::abs(w16 - reference), std::abs(w8 - reference))
      << "Scordelis-Lo: 16x16 must be closer to 0.3024 than 8x8 (convergence)";
  EXPECT_LT(std::abs(w32 - w16), std::abs(w16 - w8)) << "Scordelis-Lo: successive changes must shrink";
}

// ---- pinched hemisphere with an 18° hole ---------------------------------------------------------
// R = 10, t = 0.04, E = 6.825e7, ν = 0.3; four alternating radial forces F = 2 at the equator.
// Quarter model as a shell of revolution about x (pole on +x, the hole's edge at latitude 72°):
// φ ∈ [0, 90°] with symmetry planes y = 0 (φ = 0) and z = 0 (φ = 90°); each load point lies on a
// symmetry plane, so the quarter carries F/2 = 1 there. One axial DOF removes the x translation.
struct HemisphereResult {
  double outward = 0.0, inward = 0.0;  // radial displacements under the two loads
};

HemisphereResult pinched_hemisphere(int n) {
  const IsotropicShell shell{6.825e7, 0.3, 0.04};
  const double d = face_distance(shell), radius = 10.0;
  const ShellMesh mesh = revolution_mesh(sphere_meridian(radius), uniform_values(0, radius * degrees(72), n),
                                         uniform_values(0, kPi / 2, n), false, -d / 2, d / 2);
  const std::vector<ElementSection> sections(mesh.element_count(), emulated_section(shell));
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::v_min), {1}));
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::v_max), {2}));
  const int a = mesh.pair_index(0, 0);  // equator, φ = 0: at (0, 0, −R), outward = −z
  const int b = mesh.pair_index(0, n);  // equator, φ = 90°: at (0, R, 0), outward = +y
  dofs.fix(inner_dof(mesh.pair_index(n, 0), 0));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  add_split_force(f, a, Eigen::Vector3d(0, 0, -1.0));  // outward F/2
  add_split_force(f, b, Eigen::Vector3d(0, -1.0, 0));  // inward F/2
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::linear));
  forms.push_back(std::make_unique<NodalLoadForm>(f));
  NonlinearProblem problem(dofs, std::move(forms));
  const Eigen::VectorXd u = solve_linear(problem, kLinearResidualTolerance);
  return {-mid_displacement(u, a).z(), -mid_displacement(u, b).y()};
}

TEST(ShellBenchmarks, PinchedHemisphere) {
  constexpr double reference = 0.094;
  // Coarse meshes are not monotone (4x4 0.0963, 8x8 0.0934, 12x12 0.0930); from 12x12 on the answer
  // rises steadily towards the reference (16x16 0.0930, 32x32 0.0933, 48x48 0.0934).
  const HemisphereResult r8 = pinched_hemisphere(8), r16 = pinched_hemisphere(16), r32 = pinched_hemisphere(32);
  std::printf("  pinched hemisphere: 8x8 %.5f (%.4f), 16x16 %.5f / %.5f (%.4f), 32x32 %.5f (%.4f); reference %.3f\n",
              r8.outward, r8.outward / reference, r16.outward, r16.inward, r16.outward / reference, r32.outward,
              r32.outward / reference, reference);
  EXPECT_NEAR(r16.outward, reference, 0.03 * reference)
      << "pinched hemisphere, 16x16 quarter, linear: 0.094 (MacNeal & Harder 1985), tolerance 3%";
  EXPECT_NEAR(r16.inward, reference, 0.03 * reference) << "pinched hemisphere, inward load point, tolerance 3%";
  EXPECT_NEAR(r32.outward, reference, 0.03 * reference) << "pinched hemisphere, 32x32 quarter, tolerance 3%";
  EXPECT_LT(std::abs(r32.outward - reference), std::abs(r16.outward - reference))
      << "pinched hemisphere: 32x32 must be closer to 0.094 than 16x16 (convergence)";
}

// ---- MacNeal–Harder straight cantilever, in-plane shear ----------------------------------------------
// L = 6, width 0.2, t = 0.1, E = 1e7, ν = 0.3, 6 × 1 rectangular elements (aspect ratio 5), clamped at the
// root, a unit load at the tip in the plane, across the strip: reference tip deflection 0.1081 (MacNeal
// & Harder 1985). The faces bend in their own plane: the paper's bilinear faces lock in parasitic shear,
// the enhanced ones (mesh.faces = "enhanced") do not.
double macneal_harder_in_plane_shear(bool enhanced) {
  const IsotropicShell shell{1e7, 0.3, 0.1};
  const double d = face_distance(shell);
  const ShellMesh mesh = plate_mesh(6.0, 0.2, 6, 1, -d / 2, d / 2);
  ElementSection section = emulated_section(shell);
  section.enhanced_faces = enhanced;
  const std::vector<ElementSection> sections(mesh.element_count(), section);
  const std::vector<int> tip = mesh.edge_pairs(GridEdge::u_max);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int p : tip) add_split_force(f, p, Eigen::Vector3d(0, 1.0 / tip.size(), 0));
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::linear));
  forms.push_back(std::make_unique<NodalLoadForm>(f));
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0, 1, 2}));
  NonlinearProblem problem(dofs, std::move(forms));
  const Eigen::VectorXd u = solve_linear(problem, kLinearResidualTolerance);
  return mean_mid_displacement(u, tip).y();
}

TEST(ShellBenchmarks, MacNealHarderInPlaneShearWithEnhancedFaces) {
  const double enhanced = macneal_harder_in_plane_shear(true), compatible = macneal_harder_in_plane_shear(false);
  std::printf("  MacNeal-Harder in-plane shear: enhanced faces %.5f (%.4f), compatible %.5f (%.4f); reference 0.1081\n",
              enhanced, enhanced / 0.1081, compatible, compatible / 0.1081);
  EXPECT_NEAR(enhanced, 0.1081, 0.03 * 0.1081) << "MacNeal & Harder (1985), tolerance 3%";
}

// ---- nonlinear cantilevers (Sze, Liu & Lo 2004) -----------------------------------------------------
// L × b × h with E = 1.2e6, ν = 0, clamped (both faces) at x = 0; plate in the x-y plane, z up.
struct Cantilever {
  double length = 10.0;
  int nx = 16;
  IsotropicShell shell{1.2e6, 0.0, 0.1};
};

struct CantileverModel {
  ShellMesh mesh;
  std::vector<ElementSection> sections;
  std::vector<int> tip;
};

// The strip of the roll-up and column tests: L = 12, b = 1, h = 0.1, E = 1.2e6 → EI = 100, 32 elements.
Cantilever strip() {
  Cantilever c;
  c.length = 12.0;
  c.nx = 32;
  return c;
}

// Both faces held in x, y and z at the root (x = 0).
DofMap clamped_at_root(const ShellMesh& mesh) {
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0, 1, 2}));
  return dofs;
}

// The cantilever clamped at its root with a dead load `total` shared by its tip nodes.
std::unique_ptr<NonlinearProblem> tip_loaded_cantilever(const CantileverModel& m, const Eigen::Vector3d& total) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.mesh.dof_count());
  for (int p : m.tip) add_split_force(f, p, total / static_cast<double>(m.tip.size()));
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(m.mesh, m.sections, Kinematics::nonlinear));
  forms.push_back(std::make_unique<NodalLoadForm>(f));
  return std::make_unique<NonlinearProblem>(clamped_at_root(m.mesh), std::move(forms));
}

std::unique_ptr<CantileverModel> cantilever_model(const Cantilever& c) {
  auto m = std::make_unique<CantileverModel>();
  const double d = face_distance(c.shell);
  m->mesh = plate_mesh(c.length, 1.0, c.nx, 1, -d / 2, d / 2);
  m->sections.assign(m->mesh.element_count(), emulated_section(c.shell));
  m->tip = m->mesh.edge_pairs(GridEdge::u_max);
  return m;
}

TEST(ShellBenchmarks, SzeCantileverEndShear) {
  // P_max = 4 at the tip; reference (P/P_max: −u, w) from Sze, Liu & Lo (2004), VERIFICATION.md §3.
  struct Row {
    double level, minus_u, w;
  };
  const std::vector<Row> table{{0.05, 0.026, 0.663}, {0.25, 0.563, 3.015}, {0.5, 1.604, 4.933},
                               {0.75, 2.541, 6.031}, {1.0, 3.286, 6.698}};
  const Cantilever c;
  const auto m = cantilever_model(c);
  const ShellMesh& mesh = m->mesh;
  const auto problem = tip_loaded_cantilever(*m, Eigen::Vector3d(0, 0, 4.0));
  NewtonSolver newton(*problem, benchmark_newton_settings());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
  size_t next = 0;
  for (int k = 1; k <= 40; ++k) {  // load steps of P_max/40 up to each tabulated level
    const double level = k / 40.0;
    const NewtonOutcome out = newton.solve(u, level);
    ASSERT_TRUE(out.converged) << "Sze cantilever: Newton failed at P/Pmax = " << level;
    if (next < table.size() && std::abs(level - table[next].level) < 1e-12) {
      const Eigen::Vector3d tip = mean_mid_displacement(u, m->tip);
      const Row& row = table[next++];
      std::printf("  Sze end shear P/Pmax %.2f: -u %.4f (ref %.3f, %+.2f%%), w %.4f (ref %.3f, %+.2f%%)\n",
                  row.level, -tip.x(), row.minus_u, 100 * (-tip.x() / row.minus_u - 1), tip.z(), row.w,
                  100 * (tip.z() / row.w - 1));
      EXPECT_NEAR(tip.z(), row.w, 0.03 * row.w)
          << "Sze cantilever w at P/Pmax = " << row.level << " (Sze, Liu & Lo 2004), tolerance 3%";
      EXPECT_NEAR(-tip.x(), row.minus_u, 0.03 * row.minus_u)
          << "Sze cantilever -u at P/Pmax = " << row.level << " (Sze, Liu & Lo 2004), tolerance 3%";
    }
  }
  EXPECT_EQ(next, table.size());
}

TEST(ShellBenchmarks, CantileverRolledUpByEndMoment) {
  // L = 12, b = 1, h = 0.1, E = 1.2e6 → EI = 100; M_max = 50π/3 = 2π EI/L closes a full circle.
  // Exact: −u = L − (EI/M) sin(ML/EI), w = (EI/M)(1 − cos(ML/EI)). Error measured as the distance of
  // the FE tip from the exact tip, relative to L; tolerance 2%.
  const Cantilever c = strip();
  const auto m = cantilever_model(c);
  const ShellMesh& mesh = m->mesh;
  const double ei = 100.0, m_max = 50.0 * kPi / 3.0;
  const DofMap dofs = clamped_at_root(mesh);
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, m->sections, Kinematics::nonlinear));
  // The tip turns from +x towards +z: a rotation about −y.
  forms.push_back(std::make_unique<EndMomentForm>(mesh, m->tip, std::vector<double>(m->tip.size(), m_max / m->tip.size()),
                                                  Eigen::Vector3d(0, -1, 0)));
  NonlinearProblem problem(dofs, std::move(forms));
  NewtonSolver newton(problem, benchmark_newton_settings());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
  const int steps = 40;
  for (int k = 1; k <= steps; ++k) {
    const double level = static_cast<double>(k) / steps;
    const NewtonOutcome out = newton.solve(u, level);
    ASSERT_TRUE(out.converged) << "roll-up: Newton failed at M/Mmax = " << level;
    if (k % 10 != 0 && k != 5) continue;
    const double moment = level * m_max, radius = ei / moment, angle = moment * c.length / ei;
    const double exact_u = c.length - radius * std::sin(angle), exact_w = radius * (1 - std::cos(angle));
    const Eigen::Vector3d tip = mean_mid_displacement(u, m->tip);
    const double error = std::hypot(-tip.x() - exact_u, tip.z() - exact_w) / c.length;
    std::printf("  roll-up M/Mmax %.3f: -u %.4f (exact %.4f), w %.4f (exact %.4f), tip error %.3f%% of L\n", level,
                -tip.x(), exact_u, tip.z(), exact_w, 100 * error);
    EXPECT_LT(error, 0.02) << "end-moment cantilever at M/Mmax = " << level
                           << ": exact elastica (VERIFICATION.md §3), tolerance 2% of L";
  }
}

// ---- a bifurcation: the cantilever column past its Euler load --------------------------------------
// The strip of the roll-up test (EI = 100, L = 12) under a dead axial end load P = 1.4 P_cr,
// P_cr = π²EI/(4L²). The straight column is an equilibrium at any load, unstable beyond P_cr: Newton
// converging to the nearest equilibrium from the unloaded state finds it, and must report its tangent
// indefinite; below P_cr (0.9 P_cr) the same state is stable.
TEST(ShellBenchmarks, CantileverColumnPastItsEulerLoadIsReportedUnstable) {
  const Cantilever c = strip();
  const auto m = cantilever_model(c);
  const ShellMesh& mesh = m->mesh;
  const double ei = 100.0, p_cr = kPi * kPi * ei / (4 * c.length * c.length);
  const auto solve = [&](double ratio) {
    const auto problem = tip_loaded_cantilever(*m, Eigen::Vector3d(-ratio * p_cr, 0, 0));
    NewtonSolver newton(*problem, benchmark_newton_settings());
    Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
    const NewtonOutcome out = newton.solve(u, 1.0);
    const Eigen::Vector3d tip = mean_mid_displacement(u, m->tip);
    std::printf("  column at P/Pcr %.3f: converged %d in %d iterations, tip -u %.2e, w %.1e, tangent shift %.0e\n",
                ratio, out.converged, out.iterations, -tip.x(), tip.z(), out.final_shift);
    EXPECT_TRUE(out.converged);
    EXPECT_NEAR(tip.z(), 0.0, 1e-9) << "the nearest equilibrium is the straight column";
    return out.final_shift;
  };
  EXPECT_EQ(solve(0.9), 0.0) << "below the Euler load the straight column is stable";
  EXPECT_GT(solve(1.4), 0.0) << "past the Euler load the straight column is unstable (indefinite tangent)";
}

}  // namespace
}  // namespace tirefem::verification
