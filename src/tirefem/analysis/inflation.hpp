#pragma once
// Inflation of the tyre on its rim: the pressure is ramped from 0 to p by load stepping (Newton inside).
#include <string>

#include "tirefem/case/case.hpp"
#include "tirefem/element/element_geometry.hpp"
#include "tirefem/analysis/mesh_transfer.hpp"
#include "tirefem/solver/newton.hpp"
#include "tirefem/tyre/tyre_mesh.hpp"

namespace tirefem {

struct SolveCounters {
  int load_steps = 0;
  int cutbacks = 0;
  int newton_iterations = 0;
  int factorizations = 0;
  int assemblies = 0;
  double assembly_s = 0.0;
  double analysis_s = 0.0;  // symbolic analysis of the sparse pattern
  double factorization_s = 0.0;
  double solve_s = 0.0;
  double wall_s = 0.0;
  bool used_lu = false;
  int failed_cholesky = 0;         // factorisations that found the tangent indefinite
  int shifted_factorizations = 0;  // Cholesky with an inertia shift
  int schur_factorizations = 0;  // LUs by CholeskySchurLU (the rest of the LUs: UMFPACK's)
  int failed_schur = 0;          // its attempts that found the symmetric rest indefinite
  int schur_block = 0;           // the largest unsymmetric block it factorised
  int krylov_solves = 0;      // Newton systems solved by GMRES on a reused factorisation
  int krylov_failures = 0;
  int krylov_iterations = 0;
  double krylov_s = 0.0;
  double factor_flops = 0.0;  // of one Cholesky factorisation (0: none done)
  double factor_nonzeros = 0.0;  // in its factor L
  int solves = 0;                // triangular solves (forward and backward), GMRES's included
  int single_precision_solves = 0;  // of them, with a Cholesky factor in single precision
};

// Adds the work of a Newton solver and its problem (iterations, factorisations, times) to c.
void add_counters(SolveCounters& c, const NewtonSolver& newton, const NonlinearProblem& problem);
// Adds the work counted in `from` (e.g. a failed attempt before the one counted in `to`).
void add_counters(SolveCounters& to, const SolveCounters& from);

struct InflationResult {
  bool converged = false;
  Kinematics kinematics = Kinematics::nonlinear;
  double pressure = 0.0;
  Eigen::VectorXd displacement;
  std::vector<LoadStepRecord> steps;
  SolveCounters counters;
  std::string failure;  // when not converged: where it stopped, the residual, the fields to check
  // Stability of the inflated state (nonlinear theory): 0 when its tangent is positive definite, > 0 (the
  // shift that makes it so, NewtonOutcome::final_shift) when the tyre is unstable already when inflated:
  // on a mesh too coarse round the circumference, a mesh-scale mode (README, "How fine a mesh").
  double tangent_shift = 0.0;
  std::string instability;  // when tangent_shift > 0: what it is and what to change
};

// The length of the mesh's longest element round the circumference, at the equator's carcass radius, mm.
double longest_circumferential_element_mm(const TyreMesh& tyre_mesh);

InflationResult run_inflation(const TyreMesh& tyre_mesh, const InflationSettings& settings,
                              const ProgressSink& progress = {});
// The same from the inflated state of another mesh of the tyre with the same meridional stations (another
// number of elements round it): the inflated tyre is axisymmetric, so that state turned onto this mesh's
// node rows starts Newton at the full pressure close to this mesh's own state. The example's 80 × 46
// model from its 120 × 46 one: 4 Newton iterations and 2 factorisations instead of 10 and 4, the same
// state as the ramp's to 9e-11 mm. If Newton does not converge from there, the ramp follows.
InflationResult run_inflation_from(const TyreMesh& tyre_mesh, const InflationSettings& settings,
                                   const TyreMesh& from, const Eigen::VectorXd& inflated_from,
                                   const ProgressSink& progress = {});

}  // namespace tirefem
