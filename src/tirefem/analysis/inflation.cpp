#include "tirefem/analysis/inflation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "tirefem/forms/pressure_form.hpp"
#include "tirefem/analysis/tyre_shell_forms.hpp"

namespace tirefem {

namespace {

std::unique_ptr<NonlinearProblem> inflation_problem(const TyreMesh& tm, double pressure,
                                                    Kinematics kinematics) {
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  add_tyre_shell_forms(forms, tm, kinematics);
  // The inflated surface is closed by the rim (bead held) and, in the half model, the symmetry plane,
  // so the pressure's load stiffness is symmetric in the sum (see PressureForm).
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, pressure, kinematics,
                                                 /*symmetrize=*/true));
  return std::make_unique<NonlinearProblem>(std::move(dofs), std::move(forms));
}

// Inexact Newton: a factorisation is reused as GMRES preconditioner for the next tangents while that
// converges fast. The 120 × 46 example: 4 Cholesky factorisations instead of 12 (2 Cholesky attempts and
// 10 LU), the same 10 Newton iterations, the inflated state the same to 1.4e-9 of each column's scale.
NewtonSettings inflation_newton_settings(const InflationSettings& settings) {
  NewtonSettings n;
  n.max_iterations = settings.max_newton_iterations;
  n.residual_tolerance = settings.residual_tolerance;
  n.reuse_factorization = true;
  return n;
}

// The inflated state's stability (nonlinear theory), from the last solve's own test, or from one made here
// when that solve took no step (NewtonSolver tests only states it stepped to); said on the progress.
void judge_stability(InflationResult& r, NewtonSolver& newton, const LoadStepRecord& last, const TyreMesh& tm,
                     const ProgressSink& progress) {
  r.tangent_shift = last.iterations > 0 ? last.tangent_shift : newton.stability_shift();
  if (r.tangent_shift <= 0.0) return;
  r.instability = fmt::format(
      "the inflated tyre is unstable on the {} x {} {} mesh (its tangent is indefinite): with this model a "
      "mesh-scale mode of too coarse a mesh (README, \"How fine a mesh\"; here elements up to {:.0f} mm long "
      "round the circumference at the crown): refine it, mesh.circumferential_elements first (or a smaller "
      "circumferential_refinement), else meridional_elements",
      tm.mesh.v_elements(), tm.half_model ? tm.mesh.u_elements() : tm.mesh.u_elements() / 2,
      tm.half_model ? "half" : "full", longest_circumferential_element_mm(tm));
  if (progress) progress("  warning: " + r.instability);
}

}  // namespace

double longest_circumferential_element_mm(const TyreMesh& tm) {
  const std::vector<double>& phi = tm.mesh.v_values;
  double longest = 0.0;
  for (std::size_t k = 1; k < phi.size(); ++k) longest = std::max(longest, std::abs(phi[k] - phi[k - 1]));
  return longest * tm.profile.point(0.0)[1];
}

void add_counters(SolveCounters& to, const SolveCounters& from) {
  to.load_steps += from.load_steps;
  to.cutbacks += from.cutbacks;
  to.newton_iterations += from.newton_iterations;
  to.factorizations += from.factorizations;
  to.assemblies += from.assemblies;
  to.assembly_s += from.assembly_s;
  to.analysis_s += from.analysis_s;
  to.factorization_s += from.factorization_s;
  to.solve_s += from.solve_s;
  to.wall_s += from.wall_s;
  to.used_lu = to.used_lu || from.used_lu;
  to.failed_cholesky += from.failed_cholesky;
  to.shifted_factorizations += from.shifted_factorizations;
  to.schur_factorizations += from.schur_factorizations;
  to.failed_schur += from.failed_schur;
  to.schur_block = std::max(to.schur_block, from.schur_block);
  to.krylov_solves += from.krylov_solves;
  to.krylov_failures += from.krylov_failures;
  to.krylov_iterations += from.krylov_iterations;
  to.krylov_s += from.krylov_s;
  to.solves += from.solves;
  to.single_precision_solves += from.single_precision_solves;
}

void add_counters(SolveCounters& c, const NewtonSolver& newton, const NonlinearProblem& problem) {
  const LinearSolverStats& l = newton.linear_stats();
  c.newton_iterations += newton.total_iterations();
  c.factorizations += l.factorizations;
  c.analysis_s += l.analysis_s;
  c.factorization_s += l.factorization_s;
  c.solve_s += l.solve_s;
  c.used_lu = c.used_lu || l.used_lu;
  c.failed_cholesky += l.failed_cholesky;
  c.shifted_factorizations += l.shifted_factorizations;
  c.schur_factorizations += l.schur_factorizations;
  c.failed_schur += l.failed_schur;
  c.schur_block = std::max(c.schur_block, l.schur_block);
  c.krylov_solves += l.krylov_solves;
  c.krylov_failures += l.krylov_failures;
  c.krylov_iterations += l.krylov_iterations;
  c.krylov_s += l.krylov_s;
  c.factor_flops = std::max(c.factor_flops, l.factor_flops);
  c.factor_nonzeros = std::max(c.factor_nonzeros, l.factor_nonzeros);
  c.solves += l.solves;
  c.single_precision_solves += l.single_precision_solves;
  c.assemblies += problem.stats().assemblies;
  c.assembly_s += problem.stats().assembly_s;
}

InflationResult run_inflation(const TyreMesh& tm, const InflationSettings& settings,
                              const ProgressSink& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  InflationResult result;
  result.kinematics = settings.linear ? Kinematics::linear : Kinematics::nonlinear;
  result.pressure = settings.pressure;

  const NewtonSettings newton_settings = inflation_newton_settings(settings);
  SolveCounters& c = result.counters;
  result.displacement = Eigen::VectorXd::Zero(tm.mesh.dof_count());

  // Pressure ramp λ p. (A linear-theory predictor does not help here: without the hoop-tension stiffening
  // the radial-ply sidewall moves about four times too far, so Newton starts from the unloaded state.)
  const Kinematics kinematics = result.kinematics;
  auto problem = inflation_problem(tm, settings.pressure, kinematics);
  if (progress)
    progress(fmt::format("inflation to {} MPa ({} theory): {} equations", settings.pressure,
                         settings.linear ? "linear" : "nonlinear", problem->dofs().equation_count()));
  NewtonSolver newton(*problem, newton_settings);
  const LoadPathResult path =
      follow_load_path(newton, result.displacement, LoadSteppingSettings{}, {}, progress);
  add_counters(c, newton, *problem);
  result.converged = path.completed;
  result.steps = path.steps;
  if (!path.completed)
    result.failure = fmt::format(
        "inflation to {} MPa did not converge: reached {:.0f}% of the pressure, then Newton stopped at a "
        "residual of {:.1e} after {} cut-backs; check tyre.profile.points (inside out? crossing itself?), "
        "the plies' cord_modulus and thickness and tyre.interlayer.thickness, or raise "
        "inflation.max_newton_iterations",
        settings.pressure, 100.0 * (path.steps.empty() ? 0.0 : path.steps.back().load_factor),
        path.last_failure.relative_residual, path.cutbacks);

  if (path.completed && !settings.linear) judge_stability(result, newton, path.steps.back(), tm, progress);
  c.load_steps = static_cast<int>(path.steps.size());
  c.cutbacks = path.cutbacks;
  c.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

InflationResult run_inflation_from(const TyreMesh& tm, const InflationSettings& settings, const TyreMesh& from,
                                   const Eigen::VectorXd& inflated_from, const ProgressSink& progress) {
  if (settings.linear) return run_inflation(tm, settings, progress);
  const auto t0 = std::chrono::steady_clock::now();
  InflationResult result;
  result.kinematics = Kinematics::nonlinear;
  result.pressure = settings.pressure;
  result.displacement = turned_onto(from, inflated_from, tm);
  auto problem = inflation_problem(tm, settings.pressure, Kinematics::nonlinear);
  if (progress)
    progress(fmt::format("inflation to {} MPa (nonlinear theory): {} equations, from the inflated {} x {} mesh",
                         settings.pressure, problem->dofs().equation_count(), from.mesh.v_elements(),
                         from.mesh.u_elements()));
  NewtonSolver newton(*problem, inflation_newton_settings(settings));
  const NewtonOutcome out = newton.solve(result.displacement, 1.0);
  if (progress) {
    std::string residuals;
    for (double r : out.residual_history) residuals += fmt::format(" {:.1e}", r);
    progress(fmt::format("  load factor 1.0000: {} Newton iterations, residuals{}{}", out.iterations, residuals,
                         out.converged ? "" : " (not converged: the pressure ramp from the unloaded tyre follows)"));
  }
  if (!out.converged) return run_inflation(tm, settings, progress);
  add_counters(result.counters, newton, *problem);
  result.converged = true;
  result.steps = {LoadStepRecord{1.0, out.iterations, out.relative_residual, out.final_shift}};
  judge_stability(result, newton, result.steps.back(), tm, progress);
  result.counters.load_steps = 1;
  result.counters.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace tirefem
