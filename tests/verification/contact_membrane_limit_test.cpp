// exploration
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>

#include "contact_support.hpp"

namespace tirefem::verification {
namespace {

TEST(ContactMembraneLimit, Explore) {
  const Stopwatch clock;
  Case c = example_case();
  const double shear_scale = std::getenv("SHEAR") ? std::atof(std::getenv("SHEAR")) : 1e-3;
  const double normal_scale = std::getenv("NORMAL") ? std::atof(std::getenv("NORMAL")) : 1.0;
  const double kp = std::getenv("KP") ? std::atof(std::getenv("KP")) : 100.0;
  const int nc = std::getenv("NC") ? std::atoi(std::getenv("NC")) : 48;
  const int nm = std::getenv("NM") ? std::atoi(std::getenv("NM")) : 12;
  const double dmax = std::getenv("DMAX") ? std::atof(std::getenv("DMAX")) : 20.0;
  const int pts = std::getenv("PTS") ? std::atoi(std::getenv("PTS")) : 4;
  for (Zone& z : c.tyre.zones) {
    z.core_shear_modulus *= shear_scale;
    z.core_normal_modulus *= normal_scale;
  }
  c.tyre.tread_stiffness = kp;
  const TyreMesh tm = build_tyre_mesh(c.tyre, coarse_mesh(nc, nm, true));
  const StaticContactResult r = run_load_curve(tm, c.tyre, c.inflation, test_contact_settings(),
                                               load_curve("m", plane_support(), dmax, pts),
                                               [](const std::string& s) { std::printf("%s\n", s.c_str()); });
  for (const LoadPoint& p : r.points)
    std::printf("δ %.2f Qz %.1f area %.1f pA %.1f ratio %.4f mean p %.4f max %.4f L %.1f W %.1f\n", p.deflection_mm,
                p.patch.Qz_N, p.patch.contact_area_mm2, 0.2 * p.patch.contact_area_mm2,
                p.patch.Qz_N / (0.2 * p.patch.contact_area_mm2), p.patch.mean_pressure_MPa, p.patch.max_pressure_MPa,
                p.patch.patch_length_mm, p.patch.patch_width_mm);
  std::printf("completed %d %s  %.1f s\n", r.completed, r.failure.c_str(), clock.seconds());
}

}  // namespace
}  // namespace tirefem::verification
