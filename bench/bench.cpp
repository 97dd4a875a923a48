// Benchmark of the standard runs on the example tyre (not a test): prints DOF, iterations,
// factorisations and where the time goes.
// Usage: tirefem_bench [CASE.toml [two_level|single_loop]]   inflation + the plane load curve 0–40 mm
//        tirefem_bench inflation [CASE.toml]                  the inflation alone
//        tirefem_bench rolling [CASE.toml]                    one rolling state + a 15-point slip sweep
//                                                             (mesh and μ of the case's first rolling study)
//        tirefem_bench cornering [CASE.toml [MERIDIONAL]]     one state at α = 2° + an 11-point α sweep on
//                                                             the full model of that study's mesh (with
//                                                             MERIDIONAL elements per half if given); no
//                                                             case: the cornering example at 80 × 46
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <omp.h>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/inflation.hpp"
#include "tirefem/analysis/rolling.hpp"
#include "tirefem/case/case_reader.hpp"
#include "tirefem/report/shell_results.hpp"
#include "tirefem/solver/blas_kernel.hpp"
#include "tirefem/solver/heap_settings.hpp"

namespace {

void print_counters(const std::string& name, const tirefem::SolveCounters& c) {
  fmt::print("{}\n", name);
  fmt::print("  load steps            {:>8}   (cut-backs {})\n", c.load_steps, c.cutbacks);
  fmt::print("  Newton iterations     {:>8}\n", c.newton_iterations);
  fmt::print("  factorisations        {:>8}   ({})\n", c.factorizations,
             c.used_lu ? "LU, CHOLMOD Cholesky" : "CHOLMOD supernodal Cholesky");
  if (c.schur_factorizations + c.failed_schur > 0)
    fmt::print("  of which               {:>7} LUs as Cholesky + dense LU of the unsymmetric block (up to {} "
               "equations), {} attempts that found the rest indefinite\n",
               c.schur_factorizations, c.schur_block, c.failed_schur);
  if (c.failed_cholesky + c.shifted_factorizations > 0)
    fmt::print("  of which               {:>7} Cholesky attempts that found the tangent indefinite, {} "
               "with an inertia shift\n",
               c.failed_cholesky, c.shifted_factorizations);
  fmt::print("  assemblies            {:>8}\n", c.assemblies);
  fmt::print("  assembly time         {:>8.3f} s\n", c.assembly_s);
  fmt::print("  symbolic analysis     {:>8.3f} s\n", c.analysis_s);
  fmt::print("  factorisation time    {:>8.3f} s  ({:.3f} s each)\n", c.factorization_s,
             c.factorizations ? c.factorization_s / c.factorizations : 0.0);
  if (c.factor_flops > 0)
    fmt::print("  Cholesky factor       {:>8.2f} GFlop each, {:.1f} M nonzeros (fill-reducing ordering chosen by CHOLMOD)\n",
               c.factor_flops * 1e-9, c.factor_nonzeros * 1e-6);
  fmt::print("  triangular solves     {:>8.3f} s  ({} solves, {:.1f} ms each; {} with a single-precision factor)\n",
             c.solve_s, c.solves, c.solves ? 1e3 * c.solve_s / c.solves : 0.0, c.single_precision_solves);
  if (c.krylov_solves + c.krylov_failures > 0)
    fmt::print("  reused factorisations {:>8}   (GMRES: {} iterations, {} given up, {:.3f} s)\n",
               c.krylov_solves, c.krylov_iterations, c.krylov_failures, c.krylov_s);
  fmt::print("  total                 {:>8.3f} s\n", c.wall_s);
  // How much of the time the counted work explains (1 = all of it; more = time spent elsewhere: solves,
  // GMRES, energy evaluations, bookkeeping).
  const double counted = c.factorization_s + c.assembly_s;
  if (counted > 0)
    fmt::print("  total / (factorisations + assemblies) {:.2f}\n", c.wall_s / counted);
}

void print_rolling_counts(const std::string& name, const tirefem::RollingSolveCounts& c) {
  fmt::print("{:<28} {:>5} Newton iterations, {:>3} factorisations, {:>2} contact iterations, {:>7.3f} s\n", name,
             c.newton_iterations, c.factorizations, c.contact_iterations, c.time_s);
}

// The solver counts of a sweep's points, added up.
tirefem::RollingSolveCounts sweep_counts(const std::vector<tirefem::SweepPoint>& points) {
  tirefem::RollingSolveCounts sum;
  for (const tirefem::SweepPoint& p : points) {
    sum.newton_iterations += p.counts.newton_iterations;
    sum.factorizations += p.counts.factorizations;
    sum.contact_iterations += p.counts.contact_iterations;
    sum.time_s += p.counts.time_s;
  }
  return sum;
}

// The rolling benchmark: on the case's rolling mesh (80 × 46 in the example), the footprint at
// 3700 N, free rolling, one state with stick and slip (κ = 0.02) and a 15-point slip sweep −0.15 … 0.15.
int rolling_benchmark(const std::string& file) {
  using namespace tirefem;
  const auto t0 = std::chrono::steady_clock::now();
  const Case c = read_case(file);
  RollingStudy study = c.rolling.empty() ? RollingStudy{} : c.rolling.front();
  const MeshSettings mesh = study.mesh.value_or(c.mesh);
  const TyreMesh tm = build_tyre_mesh(c.tyre, mesh);
  study.name = "bench";
  RollingStateSpec state;
  state.kind = RollingStateSpec::Kind::given_slip;
  state.slip = 0.02;
  study.states = {RollingStateSpec{}, state};  // free rolling (its counts), then the state
  const bool hold_load = study.sweep && study.sweep->hold_load;
  study.sweep = SlipSweep{-0.15, 0.15, 15, hold_load};
  fmt::print("tirefem rolling benchmark: {} ({} threads), {} x {} mesh, {} DOF (free {}), μ = {}\n", c.title,
             omp_get_max_threads(), mesh.circumferential_elements, mesh.meridional_elements, tm.mesh.dof_count(),
             tm.mesh.dof_count() - static_cast<int>(tm.fixed_dofs.size()), study.friction);
  const RollingResult r = run_rolling(tm, c.tyre, c.inflation, c.contact, study);
  print_counters("footprint (inflation + static loading to 3700 N)", r.footprint.counters);
  print_counters(fmt::format("rolling phase: {}", r.completed ? "completed" : "FAILED: " + r.failure), r.counters);
  const RollingSolveCounts sweep = sweep_counts(r.sweep);
  if (r.effective_rolling_radius_mm)
    fmt::print("free rolling: Re {:.3f} mm, slip stiffness {:.0f} N\n", *r.effective_rolling_radius_mm,
               r.slip_stiffness_N.value_or(0.0));
  if (!r.states.empty()) print_rolling_counts("free rolling (secant on Rk)", r.states.front().counts);
  for (std::size_t i = 1; i < r.states.size(); ++i)
    print_rolling_counts(fmt::format("one state, κ = {:g}", r.states[i].spec.slip), r.states[i].counts);
  print_rolling_counts(fmt::format("slip sweep, {} points{}", r.sweep.size(), hold_load ? ", Qz held" : ""), sweep);
  fmt::print("total                        {:.3f} s\n",
             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return r.completed ? 0 : 1;
}

// The cornering benchmark (issue 11): on the full model of the case's first rolling study's mesh, with
// `meridional` elements per half if > 0, the 3700 N footprint, free rolling, one state at α = 2° (κ = 0)
// and an 11-point α sweep −10° … 10° with the axle held (hold = "deflection"). Issue 11's mesh is the
// paper's 80 × 46 (44k equations): the default runs the cornering example (rim flange, carcass cords
// softer in compression) on it.
int cornering_benchmark(const std::string& file, int meridional) {
  using namespace tirefem;
  const auto t0 = std::chrono::steady_clock::now();
  const Case c = read_case(file);
  RollingStudy study = c.rolling.empty() ? RollingStudy{} : c.rolling.front();
  MeshSettings mesh = study.mesh.value_or(c.mesh);
  mesh.half_model = false;
  if (meridional > 0) mesh.meridional_elements = meridional;
  const TyreMesh tm = build_tyre_mesh(c.tyre, mesh);
  study.name = "bench";
  study.tread_shear.reset();  // planar on the full model
  RollingStateSpec state;
  state.kind = RollingStateSpec::Kind::given_slip;
  state.slip_angle_deg = 2.0;
  study.states = {RollingStateSpec{}, state};
  study.sweep.reset();
  study.combined.reset();
  study.angle_sweep = SlipAngleSweep{-10.0, 10.0, 11, 0.0, 0.0, false};
  study.angle_sweep->mirror_negative_angles = true;  // as a case's sweep: α < 0 mirrored where exact
  fmt::print("tirefem cornering benchmark: {} ({} threads), {} x {} full model, {} DOF (free {}), μ = {}\n", c.title,
             omp_get_max_threads(), mesh.circumferential_elements, mesh.meridional_elements, tm.mesh.dof_count(),
             tm.mesh.dof_count() - static_cast<int>(tm.fixed_dofs.size()), study.friction);
  const RollingResult r = run_rolling(tm, c.tyre, c.inflation, c.contact, study);
  print_counters("footprint (inflation + static loading to 3700 N)", r.footprint.counters);
  print_counters(fmt::format("rolling phase: {}", r.completed ? "completed" : "FAILED: " + r.failure), r.counters);
  const RollingSolveCounts sweep = sweep_counts(r.angle_sweep);
  if (!r.states.empty()) print_rolling_counts("free rolling (secant on Rk)", r.states.front().counts);
  for (std::size_t i = 1; i < r.states.size(); ++i)
    print_rolling_counts(fmt::format("one state, α = {:g}°", r.states[i].spec.slip_angle_deg), r.states[i].counts);
  const auto mirrored = std::count_if(r.angle_sweep.begin(), r.angle_sweep.end(), [](const SweepPoint& p) { return p.mirrored; });
  print_rolling_counts(fmt::format("α sweep, {} points ({} mirrored)", r.angle_sweep.size(), mirrored), sweep);
  if (r.cornering_stiffness_N_per_deg)
    fmt::print("cornering stiffness dFy/dα {:.1f} N/deg, trail {:.2f} mm (at α = 0, ±0.2°)\n",
               *r.cornering_stiffness_N_per_deg, r.pneumatic_trail_at_zero_mm.value_or(0.0));
  fmt::print("total                        {:.3f} s\n",
             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return r.completed ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tirefem;
  use_fast_blas_kernel(argv);
  const std::string allocator = keep_freed_memory();
  const BlasKernel blas = blas_kernel();
  fmt::print("BLAS: {}, kernel {}{}\n", blas.library, blas.core.empty() ? "unknown" : blas.core,
             blas.forced ? " (set by OPENBLAS_CORETYPE)" : " (detected)");
  const char* wait_policy = std::getenv("OMP_WAIT_POLICY");
  fmt::print("OpenMP wait policy: {}\n", wait_policy ? wait_policy : "libgomp's default (spinning)");
  const char* thread_limit = std::getenv("OMP_THREAD_LIMIT");
  fmt::print("OpenMP thread limit: {}\n", thread_limit ? thread_limit : "none");
  const char* thread_timeout = std::getenv("OPENBLAS_THREAD_TIMEOUT");
  fmt::print("OpenBLAS idle threads spin for 2^{} cycles\n", thread_timeout ? thread_timeout : "28 (its default)");
  fmt::print("memory allocator: {}\n", allocator);
  // "rolling [CASE]" and "cornering [CASE [MERIDIONAL]]": the rolling benchmarks.
  const std::string examples = std::string(TIREFEM_SOURCE_DIR) + "/examples/";
  try {
    if (argc >= 2 && std::string(argv[1]) == "rolling")
      return rolling_benchmark(argc > 2 ? argv[2] : examples + "175-70R13.toml");
    if (argc >= 2 && std::string(argv[1]) == "cornering") {
      int meridional = 0;
      if (argc > 3 && (std::sscanf(argv[3], "%d", &meridional) != 1 || meridional < 1))
        throw std::runtime_error(fmt::format("MERIDIONAL '{}' is not a positive number of elements", argv[3]));
      if (argc > 2) return cornering_benchmark(argv[2], meridional);
      return cornering_benchmark(examples + "175-70R13-cornering.toml", 46);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tirefem_bench: %s\n", e.what());
    return 2;
  }
  // "inflation [CASE]": the inflation alone (a quick measure of assembly and factorisation speed).
  const bool inflation_only = argc > 1 && std::string(argv[1]) == "inflation";
  if (inflation_only) --argc, ++argv;
  const std::string file = argc > 1 ? argv[1] : std::string(TIREFEM_SOURCE_DIR) + "/examples/175-70R13.toml";
  try {
    const auto t0 = std::chrono::steady_clock::now();
    Case c = read_case(file);
    const TyreMesh tm = build_tyre_mesh(c.tyre, c.mesh);
    const double setup_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fmt::print("tirefem benchmark: {} ({} threads)\n", c.title, omp_get_max_threads());
    fmt::print("  mesh                  {} x {} ({} model), {} elements\n", c.mesh.circumferential_elements,
               c.mesh.meridional_elements, c.mesh.half_model ? "half" : "full", tm.mesh.element_count());
    fmt::print("  DOF                   {:>8}   (free {})\n", tm.mesh.dof_count(),
               tm.mesh.dof_count() - static_cast<int>(tm.fixed_dofs.size()));
    fmt::print("  case + mesh           {:>8.3f} s\n", setup_s);
    const auto say = [](const std::string& m) { fmt::print("{}\n", m); };
    const InflationResult r = run_inflation(tm, c.inflation, say);
    print_counters(fmt::format("inflation to {} MPa, nonlinear: {}", c.inflation.pressure,
                               r.converged ? "converged" : "NOT CONVERGED"),
                   r.counters);
    if (inflation_only) return r.converged ? 0 : 1;
    // The benchmark: the load characteristic 0–40 mm in 20 points on the plane. Optional second
    // argument: "two_level" or "single_loop" overrides the case's contact iteration.
    if (argc > 2)
      c.contact.iteration = std::string(argv[2]) == "single_loop" ? ContactSettings::Iteration::single_loop
                                                                  : ContactSettings::Iteration::two_level;
    LoadCurveStudy study;
    study.name = "plane";
    const StaticContactResult lc = run_load_curve(tm, c.tyre, c.inflation, c.contact, study, say);
    int outer = 0;
    for (const LoadPoint& p : lc.points) outer += p.contact_iterations;
    print_counters(fmt::format("load curve 0-{} mm in {} points on the plane, {} iteration{}: {}",
                               study.max_deflection, study.points,
                               c.contact.iteration == ContactSettings::Iteration::two_level ? "two-level"
                                                                                            : "single-loop",
                               c.contact.reuse_factorizations ? ", factorisations reused" : "",
                               lc.completed ? "completed" : "FAILED: " + lc.failure),
                   lc.counters);
    fmt::print("  contact iterations    {:>8}   (outer loop, all points)\n", outer);
    // Full precision, to check that a change to the solver keeps the answers (1e-6 relative).
    fmt::print("  Qz (N) at δz (mm):");
    for (const LoadPoint& p : lc.points) fmt::print(" {:g}:{:.10g}", p.deflection_mm, p.patch.Qz_N);
    fmt::print("\n");
    fmt::print("  (the load curve's time includes its own inflation: {:.3f} s)\n", lc.inflation.counters.wall_s);
    return r.converged && lc.completed ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tirefem_bench: %s\n", e.what());
    return 2;
  }
}
