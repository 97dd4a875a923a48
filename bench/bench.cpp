// Benchmark of the standard runs on the example tyre (not a test): prints DOF, iterations,
// factorisations and where the time goes. Usage: tirefem_bench [CASE.toml]
#include <chrono>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <omp.h>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/inflation.hpp"
#include "tirefem/case/case_reader.hpp"
#include "tirefem/results/shell_results.hpp"

namespace {

void print_counters(const std::string& name, const tirefem::SolveCounters& c) {
  fmt::print("{}\n", name);
  fmt::print("  load steps            {:>8}   (cut-backs {})\n", c.load_steps, c.cutbacks);
  fmt::print("  Newton iterations     {:>8}\n", c.newton_iterations);
  fmt::print("  factorisations        {:>8}   ({})\n", c.factorizations,
             c.used_lu ? "UMFPACK LU" : "CHOLMOD supernodal Cholesky");
  fmt::print("  assemblies            {:>8}\n", c.assemblies);
  fmt::print("  assembly time         {:>8.3f} s\n", c.assembly_s);
  fmt::print("  symbolic analysis     {:>8.3f} s\n", c.analysis_s);
  fmt::print("  factorisation time    {:>8.3f} s  ({:.3f} s each)\n", c.factorization_s,
             c.factorizations ? c.factorization_s / c.factorizations : 0.0);
  fmt::print("  triangular solves     {:>8.3f} s\n", c.solve_s);
  if (c.krylov_solves + c.krylov_failures > 0)
    fmt::print("  reused factorisations {:>8}   (GMRES: {} iterations, {} given up, {:.3f} s)\n",
               c.krylov_solves, c.krylov_iterations, c.krylov_failures, c.krylov_s);
  fmt::print("  total                 {:>8.3f} s\n", c.wall_s);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tirefem;
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
    InflationSettings s = c.inflation;
    const InflationResult r = run_inflation(tm, s, [](const std::string& m) { fmt::print("{}\n", m); });
    print_counters(fmt::format("inflation to {} MPa, nonlinear: {}", s.pressure,
                               r.converged ? "converged" : "NOT CONVERGED"),
                   r.counters);
    s.linear = true;
    const InflationResult rl = run_inflation(tm, s);
    print_counters(fmt::format("inflation to {} MPa, linear: {}", s.pressure,
                               rl.converged ? "converged" : "NOT CONVERGED"),
                   rl.counters);
    LoadCurveStudy study;
    if (argc > 2) c.contact.iteration = std::string(argv[2]) == "single" ? ContactSettings::Iteration::single_loop : ContactSettings::Iteration::two_level;
    study.name = "plane";
    const StaticContactResult lc = run_load_curve(tm, c.tyre, c.inflation, c.contact, study,
                                                  [](const std::string& m) { fmt::print("{}\n", m); });
    print_counters(fmt::format("load curve 0-{} mm in {} points, plane: {}", study.max_deflection,
                               study.points, lc.completed ? "completed" : "FAILED: " + lc.failure),
                   lc.counters);
    return r.converged && rl.converged && lc.completed ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tirefem_bench: %s\n", e.what());
    return 2;
  }
}
