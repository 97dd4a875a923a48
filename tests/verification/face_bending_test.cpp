// The faces' own bending stiffness (forms/face_bending_form.hpp): its tangent against finite differences
// of its force and its force against finite differences of its energy (nonlinear and linear theory, with
// and without the symmetry plane), rigid-body motions, a plate rolled into a cylinder (½ D κ² per area),
// the half model against the full one, and the classical wrinkling load of a compressed face on an elastic
// foundation, 2√(kD). The in-plane (geodesic) bending of the lines, in all of the difference, rigid-body
// and half-model checks, and the kink load of a ply compressed along its cords, A66 + D(π/L)².
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include "form_fd_support.hpp"
#include "tirefem/forms/face_bending_form.hpp"
#include "tirefem/forms/nodal_load_form.hpp"
#include "tirefem/forms/shell_internal_force.hpp"
#include "tirefem/solver/newton.hpp"

namespace tirefem::verification {
namespace {

// Sections with bending stiffness varying from element to element, both faces, both directions.
std::vector<ElementSection> bending_sections(const ShellMesh& mesh, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(50.0, 500.0);
  std::vector<ElementSection> sections(mesh.element_count());
  for (ElementSection& s : sections) {
    s.inner_face_bending = {d(rng), d(rng)};
    s.outer_face_bending = {d(rng), d(rng)};
    s.inner_face_in_plane_bending = {d(rng), d(rng)};
    s.outer_face_in_plane_bending = {d(rng), d(rng)};
  }
  return sections;
}

// A piece of a torus-like shell starting on the symmetry plane x = 0 (u ≥ 0) or spanning it.
ShellMesh crown_mesh(double u_min, int nu) {
  return build_grid_mesh(uniform_values(u_min, 40.0, nu), uniform_values(-0.3, 0.3, 8), false,
                         [](double x, double phi) {
                           const double r = 270.0 - x * x / 600.0;  // a crown curved both ways
                           const Eigen::Vector3d dir(0.0, std::sin(phi), -std::cos(phi));
                           const Eigen::Vector3d axis(x, 0.0, 290.0);
                           return NodePairPosition{axis + r * dir, axis + (r + 3.0) * dir};
                         });
}

void expect_consistent(const ShellMesh& mesh, Kinematics kinematics, bool symmetric, const char* label,
                       ClampedUEdges clamped = {}) {
  SingleThread one_thread;
  const auto sections = bending_sections(mesh, 7);
  SingleFormProblem p(mesh, std::make_unique<FaceBendingForm>(mesh, sections, kinematics, symmetric, clamped));
  ASSERT_GT(p.form->stencil_count(), 0);
  const Eigen::VectorXd u = random_vector(mesh.dof_count(), 11, 0.8);  // mm: curvature changes ~ κ0
  const double tangent_error = max_relative_error(p.tangent(u), fd_tangent(p, u));
  std::printf("  %-40s tangent error %.2e\n", label, tangent_error);
  EXPECT_LT(tangent_error, kFdTolerance) << label;

  // Energy: central differences along a random direction against v · R.
  const Eigen::VectorXd v = random_vector(mesh.dof_count(), 12, 1.0);
  const double h = 1e-4;
  const double d_energy = (p.form->energy_change(u, u + h * v, 1.0)->change -
                           p.form->energy_change(u, u - h * v, 1.0)->change) / (2 * h);
  const double slope = v.dot(p.residual(u));
  EXPECT_NEAR(d_energy, slope, 1e-7 * std::abs(slope)) << label;
}

TEST(FaceBending, TangentAndEnergyAgreeWithFiniteDifferences) {
  expect_consistent(crown_mesh(-40.0, 6), Kinematics::nonlinear, false, "nonlinear, full crown");
  expect_consistent(crown_mesh(0.0, 4), Kinematics::nonlinear, true, "nonlinear, half crown (mirror)");
  expect_consistent(crown_mesh(0.0, 4), Kinematics::linear, true, "linear, half crown (mirror)");
  expect_consistent(crown_mesh(-40.0, 6), Kinematics::nonlinear, false, "nonlinear, full, both edges clamped",
                    {true, true});
  expect_consistent(crown_mesh(0.0, 4), Kinematics::nonlinear, true, "nonlinear, half, u_max clamped",
                    {false, true});
  expect_consistent(crown_mesh(0.0, 4), Kinematics::linear, true, "linear, half, u_max clamped", {false, true});
}

TEST(FaceBending, RigidBodyMotionsStoreNothing) {
  const ShellMesh mesh = crown_mesh(-40.0, 6);
  const auto sections = bending_sections(mesh, 3);
  SingleFormProblem p(mesh, std::make_unique<FaceBendingForm>(mesh, sections, Kinematics::nonlinear, false));
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(12.0, -30.0, 5.0);
  Eigen::VectorXd u(mesh.dof_count());
  for (int q = 0; q < mesh.pair_count(); ++q) {
    const Eigen::Vector3d in = mesh.inner_nodes[q], out = mesh.outer_nodes[q];
    u.segment<3>(inner_dof(q, 0)) = rotation * in + shift - in;
    u.segment<3>(outer_dof(q, 0)) = rotation * out + shift - out;
  }
  const Eigen::VectorXd bend = random_vector(mesh.dof_count(), 5, 1.0);
  const double scale = p.residual(bend).cwiseAbs().maxCoeff();
  EXPECT_LT(p.residual(u).cwiseAbs().maxCoeff(), 1e-9 * scale);
  EXPECT_LT(std::abs(p.form->energy_change(Eigen::VectorXd::Zero(mesh.dof_count()), u, 1.0)->change),
            1e-9 * p.form->energy_change(Eigen::VectorXd::Zero(mesh.dof_count()), bend, 1.0)->change);
}

// A flat strip L × b rolled, without stretching its centre line, into a cylinder of radius R stores
// ½ D (1/R)² per unit area at the nodes that bend (the two end rows are hinges); the second difference on
// the circle is short by (h/R)²/12, so the error falls fourfold when h halves.
double rolled_plate_energy_error(int n) {
  const double length = 60.0, width = 10.0, radius = 40.0, stiffness = 250.0;
  const ShellMesh mesh = plate_mesh(length, width, n, 2, 0.0, 2.0);
  std::vector<ElementSection> sections(mesh.element_count());
  for (ElementSection& s : sections) s.outer_face_bending = {stiffness, 0.0};
  const FaceBendingForm form(mesh, sections, Kinematics::nonlinear, false);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int q = 0; q < mesh.pair_count(); ++q) {
    const Eigen::Vector3d x = mesh.outer_nodes[q];
    const double angle = x.x() / radius;
    const Eigen::Vector3d rolled(radius * std::sin(angle), x.y(), x.z() + radius * (1.0 - std::cos(angle)));
    u.segment<3>(outer_dof(q, 0)) = rolled - x;
  }
  const double h = length / n;
  const double bent_area = (length - h) * width;  // the nodes 1 … n − 1, h each
  const double expected = 0.5 * stiffness * bent_area / (radius * radius);
  const double energy = form.energy_change(Eigen::VectorXd::Zero(mesh.dof_count()), u, 1.0)->change;
  return energy / expected - 1.0;
}

TEST(FaceBending, APlateRolledIntoACylinderStoresHalfDKappaSquared) {
  const double coarse = rolled_plate_energy_error(12), fine = rolled_plate_energy_error(24);
  std::printf("  energy error: %+.3e (h = 5 mm), %+.3e (h = 2.5 mm)\n", coarse, fine);
  const double h = 5.0, radius = 40.0;
  EXPECT_NEAR(coarse, -std::pow(h / radius, 2) / 6.0, 0.1 * std::pow(h / radius, 2) / 6.0);
  EXPECT_NEAR(coarse / fine, 4.0, 0.2);
}

// A strip clamped at x = 0 (its slope there held along +x) and bent into the parabola w = a x²: the
// second difference is exact for a quadratic, (0, 0, 2a), and the line's normal from the central chord
// is tilted by tan θ = 2ax (nonlinear theory; linear: not tilted), so every node but the free end's (a
// hinge) stores ½ D (2a cos θ)² over its tributary length, the clamped node (θ = 0, the mirror node
// beyond it) over h/2. A hinged edge stores nothing at x = 0, and nothing at all when the strip turns
// rigidly about that edge; the clamp stores the first element's turn (that is what holds a bead's flap).
TEST(FaceBending, AClampedEdgeHoldsTheSlopeOfItsFirstElement) {
  const double length = 60.0, width = 10.0, stiffness = 250.0, a = 1e-3;
  const int n = 12;
  const double h = length / n;
  const ShellMesh mesh = plate_mesh(length, width, n, 2, 0.0, 2.0);
  std::vector<ElementSection> sections(mesh.element_count());
  for (ElementSection& s : sections) s.outer_face_bending = {stiffness, 0.0};
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(mesh.dof_count());
  Eigen::VectorXd parabola = zero, turned = zero;
  const double turn = 0.01;  // rad, about the edge x = 0
  for (int q = 0; q < mesh.pair_count(); ++q) {
    const double x = mesh.outer_nodes[q].x();
    parabola[outer_dof(q, 2)] = a * x * x;
    turned[outer_dof(q, 0)] = x * (std::cos(turn) - 1.0);
    turned[outer_dof(q, 2)] = x * std::sin(turn);
  }
  for (Kinematics k : {Kinematics::linear, Kinematics::nonlinear}) {
    // ½ D (2a cos θ)² b × tributary length, over the nodes x = i h, i = 0 … n − 1.
    double expected_interior = 0.0;
    for (int i = 1; i < n; ++i) {
      const double slope = k == Kinematics::linear ? 0.0 : 2.0 * a * i * h;
      expected_interior += 0.5 * stiffness * 4.0 * a * a / (1.0 + slope * slope) * width * h;
    }
    const double expected_edge = 0.5 * stiffness * 4.0 * a * a * width * 0.5 * h;
    const FaceBendingForm clamped(mesh, sections, k, false, {true, false});
    const FaceBendingForm hinged(mesh, sections, k, false);
    const double e_clamped = clamped.energy_change(zero, parabola, 1.0)->change;
    const double e_hinged = hinged.energy_change(zero, parabola, 1.0)->change;
    EXPECT_NEAR(e_clamped / (expected_interior + expected_edge), 1.0, 1e-10);
    EXPECT_NEAR(e_hinged / expected_interior, 1.0, 1e-10);
    // A rigid turn about the clamped edge: the clamped node stores ½ (D/2 · h b)(2 sin(turn)/h)² (the
    // first chord's part normal to the clamp, also linear theory's ∇κ0 · u); the hinge nothing.
    const double e_turn = clamped.energy_change(zero, turned, 1.0)->change;
    const double expected_turn = 0.5 * (0.5 * stiffness * h * width) * std::pow(2.0 * std::sin(turn) / h, 2);
    EXPECT_NEAR(e_turn / expected_turn, 1.0, 1e-9);
    EXPECT_LT(std::abs(hinged.energy_change(zero, turned, 1.0)->change), 1e-12 * expected_turn);
  }
}

// The half model with its symmetry plane carries exactly half the energy of the full model under a
// symmetric deformation, and the same forces on its nodes off the plane.
TEST(FaceBending, TheHalfModelIsHalfOfTheFullOne) {
  const ShellMesh full = crown_mesh(-40.0, 8), half = crown_mesh(0.0, 4);
  std::vector<ElementSection> full_sections(full.element_count()), half_sections(half.element_count());
  for (auto* sections : {&full_sections, &half_sections})
    for (ElementSection& s : *sections) {
      s.outer_face_bending = s.inner_face_bending = {300.0, 200.0};
      s.outer_face_in_plane_bending = s.inner_face_in_plane_bending = {150.0, 250.0};
    }
  const FaceBendingForm full_form(full, full_sections, Kinematics::nonlinear, false);
  SingleFormProblem half_problem(half, std::make_unique<FaceBendingForm>(half, half_sections,
                                                                          Kinematics::nonlinear, true));
  SingleFormProblem full_problem(full, std::make_unique<FaceBendingForm>(full, full_sections,
                                                                          Kinematics::nonlinear, false));
  // A symmetric field: u_x odd in x, u_y and u_z even.
  auto field = [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(0.3 * x.x() * std::cos(0.1 * x.y()) / 40.0, 0.5 * std::sin(0.05 * x.x() * x.x() / 40.0),
                           -1.5 * std::cos(0.08 * x.y()) * (1.0 - x.x() * x.x() / 2000.0));
  };
  auto displacement = [&](const ShellMesh& m) {
    Eigen::VectorXd u(m.dof_count());
    for (int q = 0; q < m.pair_count(); ++q) {
      u.segment<3>(inner_dof(q, 0)) = field(m.inner_nodes[q]);
      u.segment<3>(outer_dof(q, 0)) = field(m.outer_nodes[q]);
    }
    return u;
  };
  const Eigen::VectorXd u_full = displacement(full), u_half = displacement(half);
  const double e_full = full_form.energy_change(Eigen::VectorXd::Zero(full.dof_count()), u_full, 1.0)->change;
  const double e_half =
      half_problem.form->energy_change(Eigen::VectorXd::Zero(half.dof_count()), u_half, 1.0)->change;
  EXPECT_GT(e_full, 0.0);
  EXPECT_NEAR(e_half, 0.5 * e_full, 1e-10 * e_full);
  const Eigen::VectorXd r_full = full_problem.residual(u_full), r_half = half_problem.residual(u_half);
  double largest = 0.0, worst = 0.0;
  for (int j = 0; j < half.v_nodes(); ++j)
    for (int i = 1; i < half.u_nodes(); ++i) {  // node i of the half is node 4 + i of the full mesh
      const int qh = half.pair_index(i, j), qf = full.pair_index(4 + i, j);
      for (int d = 0; d < 6; ++d) {
        largest = std::max(largest, std::abs(r_full[6 * qf + d]));
        worst = std::max(worst, std::abs(r_full[6 * qf + d] - r_half[6 * qh + d]));
      }
    }
  EXPECT_LT(worst, 1e-10 * largest);
}

// Newton's equilibrium from rest of a strip under the end loads f, with `fixed` held: whether it is stable
// (the inertia of its tangent); the caller's buckling mode must not be in it (`mode`: the outer face's
// displacement component of that mode).
bool straight_strip_is_stable(const ShellMesh& mesh, const std::vector<ElementSection>& sections,
                              const std::vector<int>& fixed, const Eigen::VectorXd& f, int mode) {
  DofMap dofs(mesh.dof_count());
  dofs.fix(fixed);
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::nonlinear));
  forms.push_back(std::make_unique<FaceBendingForm>(mesh, sections, Kinematics::nonlinear, false));
  forms.push_back(std::make_unique<NodalLoadForm>(f));
  NonlinearProblem problem(dofs, std::move(forms));
  Eigen::VectorXd u;
  const bool stable = equilibrium_from_rest_is_stable(problem, u);
  double buckled = 0.0;
  for (int q = 0; q < mesh.pair_count(); ++q) buckled = std::max(buckled, std::abs(u[outer_dof(q, mode)]));
  EXPECT_LT(buckled, 1e-9) << "the nearest equilibrium is the straight strip";
  return stable;
}

// The load between a stable and an unstable straight strip, bisected from 0.8 and 1.2 × expected to
// `precision` × expected.
double critical_load(double expected, double precision, const std::function<bool(double)>& stable_at) {
  double stable = 0.8 * expected, unstable = 1.2 * expected;
  EXPECT_TRUE(stable_at(stable));
  EXPECT_FALSE(stable_at(unstable));
  while (unstable - stable > precision * expected) {
    const double mid = 0.5 * (stable + unstable);
    (stable_at(mid) ? stable : unstable) = mid;
  }
  return 0.5 * (stable + unstable);
}

// A face on an elastic foundation of stiffness k (the interlayer, E33 / c, over a held inner face),
// compressed by N per unit width, wrinkles at N = 2√(kD) with the wavelength 2π(D/k)^¼ (the classical
// beam on a Winkler foundation). Its ends are held in z: a free end on a foundation buckles first, at
// √(kD), in a mode that decays away from it. The straight state's tangent (its inertia) decides.
bool wrinkle_free(double load, int n) {
  const double length = 240.0, core = 1.0, foundation = 1.0, stiffness = 100.0;  // k = 1 N/mm³, D = 100 N·mm
  const ShellMesh mesh = plate_mesh(length, 1.0, n, 1, 0.0, core);
  ElementSection section;
  section.inner_face = section.outer_face = isotropic_membrane(1e6, 0.0, 1.0);  // shortening 2e-5 at N_cr
  section.core_normal_modulus = foundation * core;
  section.core_shear_modulus = 1e-6;
  section.outer_face_bending = {stiffness, 0.0};
  const std::vector<ElementSection> sections(mesh.element_count(), section);
  // Both faces carry N, so the interlayer is not sheared before the face wrinkles; the inner face is
  // held across the strip, everything is held in y (a plane problem), the outer face's ends in z.
  std::vector<int> fixed;
  for (int q = 0; q < mesh.pair_count(); ++q) {
    fixed.push_back(inner_dof(q, 1));
    fixed.push_back(inner_dof(q, 2));
    fixed.push_back(outer_dof(q, 1));
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int j = 0; j <= 1; ++j) {
    fixed.push_back(inner_dof(mesh.pair_index(n / 2, j), 0));
    fixed.push_back(outer_dof(mesh.pair_index(n / 2, j), 0));
    for (int end : {0, n}) fixed.push_back(outer_dof(mesh.pair_index(end, j), 2));
    for (int face = 0; face < 2; ++face) {
      f[6 * mesh.pair_index(0, j) + 3 * face] = 0.5 * load;  // N per unit width on a strip 1 wide
      f[6 * mesh.pair_index(n, j) + 3 * face] = -0.5 * load;
    }
  }
  return straight_strip_is_stable(mesh, sections, fixed, f, 2);
}

double wrinkling_load_error(int elements) {
  const double expected = 2.0 * std::sqrt(1.0 * 100.0);  // 20 N/mm; wavelength 19.9 mm
  const double fe = critical_load(expected, 2e-4, [&](double load) { return wrinkle_free(load, elements); });
  std::printf("  wrinkling load, %d elements: FE %.3f N/mm, 2√(kD) = %.3f N/mm (%+.2f%%)\n", elements, fe,
              expected, 100 * (fe / expected - 1));
  return fe / expected - 1.0;
}

// The discretisation error, O((qh)²): under 1% at 20 elements per wave, a quarter of it at 40.
TEST(FaceBending, ACompressedFaceOnAFoundationWrinklesAtTwoRootKD) {
  const double coarse = wrinkling_load_error(240), fine = wrinkling_load_error(480);
  EXPECT_LT(std::abs(coarse), 0.01);
  EXPECT_LT(std::abs(fine), 0.0025);
  EXPECT_NEAR(coarse / fine, 4.0, 0.8);
}

// A ply compressed along its cords kinks in its own plane: the cords turn (w(x) across them, in the
// face's plane) and the rubber between them shears. With in-plane shear stiffness A66 (= G t) and the
// cords' in-plane bending stiffness D, a strip of length L with its ends held across (w = 0) stores
// ½ ∫ (A66 − N) w'² + D w''², so it kinks at N = A66 + D (π/L)² (Rosen's limit G t for D = 0, where
// every wavelength, down to the mesh's, kinks at once). Cords along x, A11 3·10⁴ N/mm (stiffer cords leave
// Newton's residual at round-off above its tolerance): the strip (4 mm wide) could also bend as a beam,
// and the shear mode's A66 b acts in series with its Euler load P_E = π² A11 b³/12L² (0.4% of A66 lower);
// its shortening (5e-5) does not count. The inner face is held, the outer one loaded and held in z.
struct PlyStrip {
  double length = 40.0, width = 4.0;  // mm
  double a11 = 3e4, a22 = 10.0, a66 = 1.0;  // N/mm
};

bool kink_free(double load, int n, double in_plane_bending) {
  const PlyStrip ply;
  const double core = 1.0;
  const ShellMesh mesh = plate_mesh(ply.length, ply.width, n, 1, 0.0, core);
  ElementSection section;
  section.outer_face = section.inner_face = MembraneStiffness::Zero();
  section.outer_face(0, 0) = section.inner_face(0, 0) = ply.a11;
  section.outer_face(1, 1) = section.inner_face(1, 1) = ply.a22;
  section.outer_face(2, 2) = section.inner_face(2, 2) = ply.a66;
  section.core_normal_modulus = 10.0;
  section.core_shear_modulus = 1e-9;  // no foundation for w
  section.outer_face_in_plane_bending = {in_plane_bending, 0.0};
  const std::vector<ElementSection> sections(mesh.element_count(), section);
  std::vector<int> fixed;
  for (int q = 0; q < mesh.pair_count(); ++q) {
    for (int c = 0; c < 3; ++c) fixed.push_back(inner_dof(q, c));
    fixed.push_back(outer_dof(q, 2));
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int j = 0; j <= 1; ++j) {
    fixed.push_back(outer_dof(mesh.pair_index(n / 2, j), 0));
    for (int end : {0, n}) fixed.push_back(outer_dof(mesh.pair_index(end, j), 1));
    f[outer_dof(mesh.pair_index(0, j), 0)] = 0.5 * load * ply.width;
    f[outer_dof(mesh.pair_index(n, j), 0)] = -0.5 * load * ply.width;
  }
  return straight_strip_is_stable(mesh, sections, fixed, f, 1);
}

double kink_load(int n, double in_plane_bending) {
  const PlyStrip ply;
  const double euler = M_PI * M_PI * ply.a11 * std::pow(ply.width, 3) / (12.0 * ply.length * ply.length);
  const double expected =
      ply.a66 / (1.0 + ply.a66 * ply.width / euler) + in_plane_bending * std::pow(M_PI / ply.length, 2);
  const double fe = critical_load(expected, 2e-5, [&](double load) { return kink_free(load, n, in_plane_bending); });
  std::printf("  kink load, D = %g N·mm, %d elements: FE %.4f N/mm, expected %.4f N/mm (%+.3f%%)\n",
              in_plane_bending, n, fe, expected, 100 * (fe / expected - 1));
  return fe / expected - 1.0;
}

// Without the cords' bending the kink load is A66 on any mesh; with D = 100 N·mm it rises by 62% and the
// second difference's error, O((πh/L)²), falls fourfold as h halves.
TEST(FaceBending, ACompressedPlyKinksInItsPlaneAtShearPlusCordBending) {
  EXPECT_LT(std::abs(kink_load(20, 0.0)), 1e-4);
  const double coarse = kink_load(20, 100.0), fine = kink_load(40, 100.0);
  EXPECT_LT(std::abs(coarse), 0.01);
  EXPECT_LT(std::abs(fine), 0.0025);
  EXPECT_NEAR(coarse / fine, 4.0, 0.8);
}

}  // namespace
}  // namespace tirefem::verification
