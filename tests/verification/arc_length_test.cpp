// Arc-length path following (src/tirefem/solver/arc_length.hpp; Riks 1979, Crisfield 1981).
//  - A shallow cylindrical roof under a central point load (the geometry and material of the hinged roof
//    of Sze, Liu & Lo 2004: R = 2540, L = 508, θ = ±0.1 rad, E = 3102.75, ν = 0.3, t = 25.4; quarter
//    model), whose load–deflection path has a limit point: the path must pass it, every point must be an
//    equilibrium, and the load at the deflections of the path must equal an independent
//    displacement-controlled solution of the same discrete equations.
//  - Landing on given load levels (crossed on the way up and again after the limit point).
//  - The Sze cantilever under end shear (no limit point): the arc-length states at the tabulated levels
//    equal the load-stepped Newton solutions.
// The hinge of the straight edges is at the inner face (its three displacements held, the outer face
// free): the three-layer element has no mid-surface hinge without a skew constraint. That moves the
// hinge line t/(2√3) below the mid-surface, so the published table is not compared with here.
#include <cstdio>

#include <gtest/gtest.h>

#include "tirefem/forms/nodal_load_form.hpp"
#include "tirefem/solver/arc_length.hpp"
#include "verification_support.hpp"

namespace tirefem::verification {
namespace {

struct Roof {
  ShellMesh mesh;
  std::vector<ElementSection> sections;
  int load_pair = 0;
  std::unique_ptr<NonlinearProblem> problem;
};

// Quarter roof: x ∈ [0, 254] (x = 0 the symmetry plane across the span, x = 254 the free curved edge),
// θ ∈ [0, 0.1] from the crown (θ = 0 symmetry, θ = 0.1 the hinged straight edge). The full roof's
// central load P = kRoofLoad × λ, a quarter of it on the quarter model, half on each face. With the hinge
// at the inner face this roof is much stiffer than the published one: its first load maximum is at
// λ ≈ 0.76, the load then falls to λ ≈ 0.54 and rises again to λ = 1 on the snapped-through roof.
constexpr double kRoofLoad = 30000.0;
std::unique_ptr<Roof> shallow_roof(int n) {
  auto roof = std::make_unique<Roof>();
  const IsotropicShell shell{3102.75, 0.3, 25.4};
  const double d = face_distance(shell);
  roof->mesh = cylinder_segment_mesh(2540.0, uniform_values(0, 254.0, n), uniform_values(0, 0.1, n), -d / 2, d / 2);
  const ShellMesh& mesh = roof->mesh;
  roof->sections.assign(mesh.element_count(), emulated_section(shell));
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0}));  // symmetry x = 0
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::v_min), {1}));  // symmetry at the crown
  for (int p : mesh.edge_pairs(GridEdge::v_max))                // hinge (at the inner face)
    for (int c = 0; c < 3; ++c) dofs.fix(inner_dof(p, c));
  roof->load_pair = mesh.pair_index(0, 0);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  add_split_force(f, roof->load_pair, Eigen::Vector3d(0, 0, -kRoofLoad / 4));
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, roof->sections, Kinematics::nonlinear));
  forms.push_back(std::make_unique<NodalLoadForm>(f));
  roof->problem = std::make_unique<NonlinearProblem>(dofs, std::move(forms));
  return roof;
}

double deflection(const Roof& roof, const Eigen::VectorXd& u) { return -mid_displacement(u, roof.load_pair).z(); }

// ‖R_free(u, λ)‖ / (max(|λ|, floor) ‖F‖): the measure of ArcLengthSettings, evaluated afresh.
double relative_residual(NonlinearProblem& problem, const Eigen::VectorXd& u, double lambda, double floor) {
  problem.evaluate(u, lambda, false);
  return problem.dofs().gather(problem.system().residual()).norm() /
         (std::max(std::abs(lambda), floor) * problem.load_scale());
}

// Displacement control, independent of the arc-length code: the deflection w of the loaded point is
// prescribed and the load factor is the unknown that goes with it (the Lagrange multiplier of w(u) = w̄,
// i.e. the reaction at the loaded point over P: the load vector is P times the gradient of w).
// Newton on (u, λ) with R(u, λ) = 0, w(u) = w̄, solved by elimination of λ.
class DisplacementControl {
 public:
  explicit DisplacementControl(Roof& roof)
      : roof_(roof), problem_(*roof.problem), linear_(problem_.symmetric()),
        c_(Eigen::VectorXd::Zero(problem_.dofs().equation_count())) {
    const DofMap& dofs = problem_.dofs();
    c_[dofs.equation(inner_dof(roof.load_pair, 2))] = -0.5;
    c_[dofs.equation(outer_dof(roof.load_pair, 2))] = -0.5;
  }
  // From the equilibrium (u, λ) to the one with deflection `target`; false without convergence.
  bool solve(Eigen::VectorXd& u, double& lambda, double target, double tolerance) {
    const DofMap& dofs = problem_.dofs();
    for (int it = 0; it < 30; ++it) {
      problem_.evaluate(u, 1.0, false);
      const Eigen::VectorXd r1 = dofs.gather(problem_.system().residual());
      problem_.evaluate(u, 0.0, true);
      const Eigen::VectorXd r0 = dofs.gather(problem_.system().residual());
      const Eigen::VectorXd r = r0 + lambda * (r1 - r0), q = r1 - r0;
      const double gap = deflection(roof_, u) - target;
      if (r.norm() <= tolerance * problem_.load_scale() && std::abs(gap) <= 1e-12 * std::max(1.0, std::abs(target)))
        return true;
      linear_.factorize(problem_.system().tangent());  // the tangent does not depend on λ (dead load)
      const Eigen::VectorXd a = linear_.solve(-r), b = linear_.solve(-q);
      const double dlambda = (-gap - c_.dot(a)) / c_.dot(b);
      dofs.scatter_add(a + dlambda * b, u);
      lambda += dlambda;
    }
    return false;
  }

 private:
  Roof& roof_;
  NonlinearProblem& problem_;
  SparseDirectSolver linear_;
  Eigen::VectorXd c_;  // gradient of w over the free DOFs
};

struct PathPoint {
  ArcLengthPoint point;
  double w = 0.0;
  double residual = 0.0;  // recomputed
};

constexpr double kTolerance = 1e-9;
constexpr double kFloor = 0.01;

struct RoofPath {
  std::unique_ptr<Roof> roof;
  ArcLengthResult result;
  std::vector<PathPoint> points;
};

RoofPath roof_path(const std::vector<double>& targets) {
  RoofPath path{shallow_roof(6), {}, {}};
  ArcLengthSettings s;
  s.initial_load_increment = 0.05;
  s.residual_tolerance = kTolerance;
  s.reference_load_factor = kFloor;
  s.target_load_factors = targets;
  s.max_load_factor = 1.0;
  s.max_steps = 100;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(path.roof->mesh.dof_count());
  std::vector<std::pair<ArcLengthPoint, Eigen::VectorXd>> states;
  path.result = follow_arc_length(*path.roof->problem, u, s, [&](const ArcLengthPoint& p, const Eigen::VectorXd& x) {
    states.emplace_back(p, x);
  });
  for (const auto& [p, x] : states)
    path.points.push_back({p, deflection(*path.roof, x), relative_residual(*path.roof->problem, x, p.load_factor, kFloor)});
  return path;
}

TEST(ArcLength, ShallowRoofPassesItsLimitPointAndMatchesDisplacementControl) {
  RoofPath path = roof_path({});
  const ArcLengthResult& r = path.result;
  std::printf("  roof: %zu points, %d steps, %d cutbacks, %d iterations, %d factorisations; %s\n", r.points.size(),
              r.steps, r.cutbacks, r.iterations, r.factorizations, r.completed ? "completed" : r.failure.c_str());
  for (const PathPoint& p : path.points)
    std::printf("    w %9.4f  lambda %9.6f  (P %8.2f)  it %d  residual %.1e%s\n", p.w, p.point.load_factor,
                kRoofLoad * p.point.load_factor, p.point.iterations, p.residual, p.point.landing ? "  landing" : "");
  ASSERT_TRUE(r.completed) << r.failure;
  // The limit point: λ rises to a maximum, then falls by a clear margin before the path reaches λ = 1.
  size_t peak = 0;
  for (size_t i = 0; i < path.points.size(); ++i)
    if (path.points[i].point.load_factor > path.points[peak].point.load_factor) peak = i;
  double lowest_after = path.points[peak].point.load_factor;
  size_t first_peak = 0;
  while (first_peak + 1 < path.points.size() &&
         path.points[first_peak + 1].point.load_factor > path.points[first_peak].point.load_factor)
    ++first_peak;
  for (size_t i = first_peak; i < path.points.size(); ++i)
    lowest_after = std::min(lowest_after, path.points[i].point.load_factor);
  const double limit = path.points[first_peak].point.load_factor;
  std::printf("  roof: first load maximum lambda %.5f (P %.1f) at w %.3f; lowest load after it lambda %.5f\n", limit,
              kRoofLoad * limit, path.points[first_peak].w, lowest_after);
  EXPECT_LT(limit, 0.99) << "the first maximum must be a limit point, not the end of the path";
  EXPECT_LT(lowest_after, limit - 0.1) << "past the limit point the load must fall";
  for (const PathPoint& p : path.points)
    EXPECT_LE(p.residual, kTolerance) << "not an equilibrium at lambda " << p.point.load_factor;

  // Independent displacement control at the deflections of the path (w increases along it here).
  for (size_t i = 1; i < path.points.size(); ++i)
    ASSERT_GT(path.points[i].w, path.points[i - 1].w) << "deflection not monotone along the path";
  DisplacementControl control(*path.roof);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(path.roof->mesh.dof_count());
  double lambda = 0.0, w = 0.0, worst = 0.0;
  int compared = 0;
  for (const PathPoint& p : path.points) {
    while (w < p.w) {  // steps of at most 1 mm of deflection to the point's
      w = std::min(w + 1.0, p.w);
      ASSERT_TRUE(control.solve(u, lambda, w, kTolerance)) << "displacement control failed at w " << w;
    }
    const double error = std::abs(lambda - p.point.load_factor) / limit;
    worst = std::max(worst, error);
    ++compared;
    EXPECT_LE(error, 1e-5) << "load at w " << p.w << ": arc length " << p.point.load_factor
                           << ", displacement control " << lambda;
  }
  std::printf("  roof: %d points compared with displacement control, largest |dlambda|/lambda_limit %.1e\n",
              compared, worst);
}

TEST(ArcLength, LandsExactlyOnTargetLoadLevels) {
  const std::vector<double> targets{0.25, 0.5, 0.6, 0.7, 0.75, 1.0};
  RoofPath path = roof_path(targets);
  ASSERT_TRUE(path.result.completed) << path.result.failure;
  // Expected landings: the crossings of each target by the path of converged step ends.
  std::vector<double> ends{0.0};
  for (const PathPoint& p : path.points)
    if (!p.point.landing) ends.push_back(p.point.load_factor);
  ends.push_back(1.0);  // the run ends on its landing at max_load_factor
  int expected = 0, landed = 0;
  for (const double t : targets)
    for (size_t i = 1; i < ends.size(); ++i)
      if (t != ends[i - 1] && (t - ends[i - 1]) * (t - ends[i]) <= 0) ++expected;
  for (const PathPoint& p : path.points) {
    if (!p.point.landing) continue;
    ++landed;
    double nearest = 1e300;
    for (const double t : targets) nearest = std::min(nearest, std::abs(p.point.load_factor - t));
    std::printf("    landing lambda %.15f  w %9.4f  %d iterations  residual %.1e\n", p.point.load_factor, p.w,
                p.point.iterations, p.residual);
    EXPECT_LE(nearest, 1e-12) << "landing off its target: " << p.point.load_factor;
    EXPECT_LE(p.residual, kTolerance) << "landing not an equilibrium at " << p.point.load_factor;
  }
  std::printf("  landings: %d (expected %d crossings)\n", landed, expected);
  EXPECT_EQ(landed, expected);
  // Levels between the lowest load after the limit point and the limit load are crossed three times: on
  // the way up, after the limit point, and on the snapped-through roof.
  for (const double t : {0.6, 0.7, 0.75}) {
    int n = 0;
    for (const PathPoint& p : path.points) n += p.point.landing && p.point.load_factor == t;
    EXPECT_EQ(n, 3) << "landings on load level " << t;
  }
  EXPECT_TRUE(path.points.back().point.landing);
  EXPECT_EQ(path.points.back().point.load_factor, 1.0);
}

// The Sze cantilever under end shear (as in shell_benchmarks_test.cpp): L = 10, b = 1, h = 0.1,
// E = 1.2e6, ν = 0, 16 elements, clamped root, P_max = 4 at the tip.
TEST(ArcLength, AgreesWithLoadSteppingWithoutLimitPoint) {
  const IsotropicShell shell{1.2e6, 0.0, 0.1};
  const double d = face_distance(shell);
  const ShellMesh mesh = plate_mesh(10.0, 1.0, 16, 1, -d / 2, d / 2);
  const std::vector<ElementSection> sections(mesh.element_count(), emulated_section(shell));
  const std::vector<int> tip = mesh.edge_pairs(GridEdge::u_max);
  DofMap dofs(mesh.dof_count());
  dofs.fix(both_faces(mesh.edge_pairs(GridEdge::u_min), {0, 1, 2}));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  for (int p : tip) add_split_force(f, p, Eigen::Vector3d(0, 0, 4.0 / tip.size()));
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(mesh, sections, Kinematics::nonlinear));
  forms.push_back(std::make_unique<NodalLoadForm>(f));
  NonlinearProblem problem(dofs, std::move(forms));

  const std::vector<double> levels{0.05, 0.25, 0.5, 0.75, 1.0};
  constexpr double tolerance = 1e-7;  // above this strip's round-off floor (shell_benchmarks_test.cpp)
  ArcLengthSettings s;
  s.initial_load_increment = 0.05;
  s.residual_tolerance = tolerance;
  s.target_load_factors = levels;
  std::vector<Eigen::Vector3d> arc_tip;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(mesh.dof_count());
  const ArcLengthResult r = follow_arc_length(problem, u, s, [&](const ArcLengthPoint& p, const Eigen::VectorXd& x) {
    if (p.landing) arc_tip.push_back(mean_mid_displacement(x, tip));
  });
  std::printf("  cantilever: %d steps, %d cutbacks, %d iterations, %d factorisations, %zu landings\n", r.steps,
              r.cutbacks, r.iterations, r.factorizations, arc_tip.size());
  ASSERT_TRUE(r.completed) << r.failure;
  ASSERT_EQ(arc_tip.size(), levels.size());

  NewtonSettings ns;
  ns.residual_tolerance = tolerance;
  NewtonSolver newton(problem, ns);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(mesh.dof_count());
  size_t next = 0;
  for (int k = 1; k <= 40; ++k) {
    const double level = k / 40.0;
    ASSERT_TRUE(newton.solve(v, level).converged) << "load stepping failed at " << level;
    if (next < levels.size() && std::abs(level - levels[next]) < 1e-12) {
      const Eigen::Vector3d t = mean_mid_displacement(v, tip);
      const double error = (arc_tip[next] - t).norm() / t.norm();
      std::printf("    P/Pmax %.2f: -u %.6f, w %.6f (load stepping -u %.6f, w %.6f), relative difference %.1e\n",
                  levels[next], -arc_tip[next].x(), arc_tip[next].z(), -t.x(), t.z(), error);
      EXPECT_LE(error, 1e-6) << "arc length and load stepping differ at P/Pmax = " << levels[next];
      ++next;
    }
  }
  EXPECT_EQ(next, levels.size());
}

}  // namespace
}  // namespace tirefem::verification
