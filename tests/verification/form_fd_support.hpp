#pragma once
// Shared set-up for the finite-difference tangent tests of the contact forms (contact_tangent_test.cpp,
// tread_friction_tangent_test.cpp): a tyre-like cylindrical patch with tread points, one form alone as a
// nonlinear problem over all DOFs, central differences of its residual and of its energy, and a guard that
// runs the many tiny assemblies on one thread.
//
// Mesh: carcass at r = 280, breaker at 283, tread 7 mm, axis 290 mm above the road, so the undeformed
// tread touches z = 0 at φ = 0; 6 × 10 elements over x ∈ [−40, 40] mm, φ ∈ [−0.35, 0.35] rad (y = r sin φ
// grows with φ), 3 × 3 tread points each. The tread points' mesh parameters are (u, v) = (x, φ).
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include <omp.h>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "tirefem/forms/winkler_contact_form.hpp"
#include "tirefem/solver/nonlinear_problem.hpp"
#include "verification_support.hpp"

namespace tirefem::verification {

// Central differences with h = 1e-5 mm on O(100 mm) coordinates: truncation O(h²·r''') and round-off
// O(ε·|r|/h) are both below 1e-9 of the tangent's largest entry, so 1e-6 is a clean pass/fail line.
inline constexpr double kFdStep = 1e-5;       // mm
inline constexpr double kFdTolerance = 1e-6;  // relative error of a tangent / derivative

inline constexpr double kAxisZ = 290.0, kCarcassR = 280.0, kBreakerR = 283.0, kTreadHeight = 7.0;

inline ShellMesh tyre_patch_mesh() {
  return build_grid_mesh(uniform_values(-40.0, 40.0, 6), uniform_values(-0.35, 0.35, 10), false,
                         [](double x, double phi) {
                           const Eigen::Vector3d dir(0.0, std::sin(phi), -std::cos(phi));
                           const Eigen::Vector3d axis(x, 0.0, kAxisZ);
                           return NodePairPosition{axis + kCarcassR * dir, axis + kBreakerR * dir};
                         });
}

inline std::vector<TreadPoint> patch_points(const ShellMesh& mesh) {
  return make_tread_points(mesh, all_elements(mesh), 3, [](double) { return kTreadHeight; });
}

// The finite differences need ~1000 assemblies of a small form each; OpenMP threads spinning at the
// barriers of so many tiny parallel loops cost seconds on a loaded machine (12 s instead of 0.06 s per
// support was observed with the load average at twice the core count). One thread for these loops.
class SingleThread {
 public:
  SingleThread() : threads_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~SingleThread() { omp_set_num_threads(threads_); }
  SingleThread(const SingleThread&) = delete;
  SingleThread& operator=(const SingleThread&) = delete;

 private:
  int threads_;
};

// A rigid surface without its curvature term (its Hessian dropped): shows how much that term contributes
// to a contact tangent.
class WithoutCurvature final : public RigidSurface {
 public:
  explicit WithoutCurvature(const RigidSurface& s) : s_(s) {}
  Penetration penetration(const Eigen::Vector3d& x, double deflection) const override {
    Penetration p = s_.penetration(x, deflection);
    p.hessian.setZero();
    return p;
  }

 private:
  const RigidSurface& s_;
};

// One form alone, assembled over all DOFs of the mesh (nothing fixed); `form` stays usable to set the
// form's state (deflection, region, plan, ...) between evaluations.
template <class F>
struct SingleFormProblem {
  SingleFormProblem(const ShellMesh& mesh, std::unique_ptr<F> f) : form(f.get()) {
    std::vector<std::unique_ptr<Form>> forms;
    forms.push_back(std::move(f));
    problem = std::make_unique<NonlinearProblem>(DofMap(mesh.dof_count()), std::move(forms));
  }
  Eigen::VectorXd residual(const Eigen::VectorXd& u) {
    problem->evaluate(u, 1.0, false);
    return problem->system().residual();
  }
  Eigen::MatrixXd tangent(const Eigen::VectorXd& u) {
    problem->evaluate(u, 1.0, true);
    return Eigen::MatrixXd(problem->system().tangent());
  }
  F* form = nullptr;
  std::unique_ptr<NonlinearProblem> problem;
};

// Central differences of the residual, column by column.
template <class Problem>
Eigen::MatrixXd fd_tangent(Problem& p, const Eigen::VectorXd& u, double step = kFdStep) {
  const int n = static_cast<int>(u.size());
  Eigen::MatrixXd k(n, n);
  Eigen::VectorXd v = u;
  for (int j = 0; j < n; ++j) {
    v[j] = u[j] + step;
    const Eigen::VectorXd plus = p.residual(v);
    v[j] = u[j] - step;
    const Eigen::VectorXd minus = p.residual(v);
    v[j] = u[j];
    k.col(j) = (plus - minus) / (2.0 * step);
  }
  return k;
}

// n values uniform in [−scale, scale], reproducible from the seed.
inline Eigen::VectorXd random_vector(int n, unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = scale * d(rng);
  return v;
}

// max |a − b| / max |b|.
inline double max_relative_error(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// |dΠ/dh − v·R| / |v·R| for the problem's free DOFs (v zero on the fixed ones).
inline double energy_gradient_error(NonlinearProblem& problem, const Eigen::VectorXd& u,
                                    const Eigen::VectorXd& free_v, double load_factor, double h) {
  const DofMap& dofs = problem.dofs();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(u.size());
  dofs.scatter_add(free_v, v);
  problem.evaluate(u, load_factor, false);
  const double slope = dofs.gather(problem.system().residual()).dot(free_v);
  const auto plus = problem.energy_change(u, u + h * v, load_factor);
  const auto minus = problem.energy_change(u, u - h * v, load_factor);
  EXPECT_TRUE(plus && minus) << "the problem should have a potential";
  if (!plus || !minus) return 1.0;
  const double fd = (plus->change - minus->change) / (2 * h);
  std::printf("  dΠ/dh %.10e, v·R %.10e, relative error %.2e\n", fd, slope, std::abs(fd - slope) / std::abs(slope));
  return std::abs(fd - slope) / std::abs(slope);
}

}  // namespace tirefem::verification
