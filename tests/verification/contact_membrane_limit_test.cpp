// exploration
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>

#include "contact_support.hpp"

namespace tirefem::verification {
namespace {

double env(const char* n, double d) { return std::getenv(n) ? std::atof(std::getenv(n)) : d; }

TEST(ContactMembraneLimit, Explore) {
  const Stopwatch clock;
  Case c = example_case();
  const double shear_scale = env("SHEAR", 1e-1), normal_scale = env("NORMAL", 1.0), kp = env("KP", 100.0);
  const int nc = env("NC", 48), nm = env("NM", 12);
  const double dmax = env("DMAX", 20.0), start = env("START", -5.0);
  const int pts = env("PTS", 4);
  for (Zone& z : c.tyre.zones) {
    z.core_shear_modulus *= shear_scale;
    z.core_normal_modulus *= normal_scale;
  }
  c.tyre.tread_stiffness = kp;
  const TyreMesh tm = build_tyre_mesh(c.tyre, coarse_mesh(nc, nm, true));
  ContactSettings cs = test_contact_settings();
  cs.max_newton_iterations = env("NEWTON", 25);
  if (env("SINGLE", 0) > 0) cs.iteration = ContactSettings::Iteration::single_loop;
  ManualContactRun run(tm, c.tyre, c.inflation, cs, plane_support(), Kinematics::nonlinear, start);
  std::printf("inflated %.1f s\n", clock.seconds());
  for (int k = 0; k <= pts; ++k) {
    const double d = k * dmax / pts;
    const auto step = run.path->advance_to(d);
    if (!step.converged) { std::printf("failed at %g: %s\n", d, step.failure.c_str()); break; }
    run.contact->set_deflection(d);
    const PatchFigures p = patch_figures(run.tread_points, run.contact->evaluate(run.path->displacement()), true);
    std::printf("δ %.2f Qz %.1f area %.1f pA %.1f ratio %.4f mean p %.4f max %.4f L %.1f W %.1f (%d cutbacks, %d newton) %.1f s\n", d,
                p.Qz_N, p.contact_area_mm2, 0.2 * p.contact_area_mm2,
                p.Qz_N / (0.2 * p.contact_area_mm2), p.mean_pressure_MPa, p.max_pressure_MPa,
                p.patch_length_mm, p.patch_width_mm, step.cutbacks, step.newton_iterations, clock.seconds());
  }
}

}  // namespace
}  // namespace tirefem::verification
