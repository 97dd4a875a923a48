// Assembly benchmark (not a test): times the residual + tangent assembly of the example's static contact
// problem (shell + follower pressure + Winkler tread on the plane) at the inflated state with the plane
// raised into the tyre, on one and on two threads, and compares the result with a saved one.
// Usage: tirefem_assembly_bench save STATE.bin [CASE.toml]      inflate, save u and one assembly (R, K)
//        tirefem_assembly_bench time STATE.bin [N] [CASE.toml]  N assemblies on 1 and 2 threads (median),
//                                                               max relative difference to the saved R, K
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <omp.h>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/inflation.hpp"
#include "tirefem/case/case_reader.hpp"
#include "tirefem/forms/pressure_form.hpp"
#include "tirefem/analysis/tyre_shell_forms.hpp"
#include "tirefem/forms/winkler_contact_form.hpp"

namespace {
using namespace tirefem;

constexpr double kDeflection = 20.0;  // mm: about a third of the example's load-curve points are past this

struct ContactProblem {
  std::unique_ptr<SupportSurface> support;
  WinklerContactForm* contact = nullptr;
  std::unique_ptr<NonlinearProblem> problem;
};

ContactProblem contact_problem(const TyreMesh& tm, const Case& c) {
  ContactProblem p;
  p.support = make_support(SupportDescription{});
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  add_tyre_shell_forms(forms, tm, Kinematics::nonlinear);
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, c.inflation.pressure,
                                                 Kinematics::nonlinear, /*symmetrize=*/true));
  auto w = std::make_unique<WinklerContactForm>(tm.mesh, tyre_tread_points(tm, c.tyre, c.contact.quadrature),
                                                c.tyre.tread_stiffness, *p.support);
  w->set_deflection(kDeflection);
  p.contact = w.get();
  forms.push_back(std::move(w));
  p.problem = std::make_unique<NonlinearProblem>(std::move(dofs), std::move(forms));
  return p;
}

void write_vector(std::ofstream& out, const double* v, std::size_t n) {
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(v), static_cast<std::streamsize>(n * sizeof(double)));
}
std::vector<double> read_vector(std::ifstream& in) {
  std::size_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  std::vector<double> v(n);
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(double)));
  if (!in) throw std::runtime_error("truncated state file");
  return v;
}

// max |a − b| / max |b|
double relative_difference(const double* a, const std::vector<double>& b) {
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  return diff / scale;
}

double median_assembly_s(NonlinearProblem& problem, const Eigen::VectorXd& u, int threads, int n) {
  omp_set_num_threads(threads);
  problem.evaluate(u, 1.0, true);  // warm-up (position caches)
  std::vector<double> t(n);
  for (double& s : t) {
    const auto t0 = std::chrono::steady_clock::now();
    problem.evaluate(u, 1.0, true);
    s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  std::sort(t.begin(), t.end());
  return t[n / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s save|time STATE.bin [N] [CASE.toml]\n", argv[0]);
    return 2;
  }
  const std::string mode = argv[1], state = argv[2];
  const int n = mode == "time" && argc > 3 ? std::stoi(argv[3]) : 10;
  const int case_arg = mode == "time" ? 4 : 3;
  const std::string file =
      argc > case_arg ? argv[case_arg] : std::string(TIREFEM_SOURCE_DIR) + "/examples/175-70R13.toml";
  try {
    const Case c = read_case(file);
    const TyreMesh tm = build_tyre_mesh(c.tyre, c.mesh);
    ContactProblem p = contact_problem(tm, c);
    if (mode == "save") {
      InflationSettings inflate = c.inflation;
      inflate.linear = false;
      const InflationResult r = run_inflation(tm, inflate);
      if (!r.converged) throw std::runtime_error("inflation did not converge");
      p.problem->evaluate(r.displacement, 1.0, true);
      const SparseMatrix& k = p.problem->system().tangent();
      std::ofstream out(state, std::ios::binary);
      write_vector(out, r.displacement.data(), r.displacement.size());
      write_vector(out, p.problem->system().residual().data(), p.problem->system().residual().size());
      write_vector(out, k.valuePtr(), k.nonZeros());
      fmt::print("saved {} DOF, {} tangent entries to {}\n", r.displacement.size(), k.nonZeros(), state);
      return 0;
    }
    std::ifstream in(state, std::ios::binary);
    const std::vector<double> u_saved = read_vector(in), r_saved = read_vector(in), k_saved = read_vector(in);
    const Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd>(u_saved.data(), u_saved.size());
    NonlinearProblem& problem = *p.problem;
    const double t1 = median_assembly_s(problem, u, 1, n);
    const double t2 = median_assembly_s(problem, u, 2, n);
    const SparseMatrix& k = problem.system().tangent();
    if (static_cast<std::size_t>(k.nonZeros()) != k_saved.size()) throw std::runtime_error("pattern changed");
    fmt::print("{} DOF, {} elements, {} tread points; median of {} assemblies (residual + tangent)\n", u.size(),
               tm.mesh.element_count(), p.contact->points().size(), n);
    fmt::print("  1 thread   {:.4f} s\n  2 threads  {:.4f} s\n", t1, t2);
    fmt::print("  max relative difference to the saved assembly: residual {:.2e}, tangent {:.2e}\n",
               relative_difference(problem.system().residual().data(), r_saved),
               relative_difference(k.valuePtr(), k_saved));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
