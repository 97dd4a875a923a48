// A wrinkling-prone tyre (issue 9): the steel belt face on a soft, thick interlayer at low inflation
// (tests/verification/data/wrinkling_tyre.toml). Its load curve 0–40 mm in 20 points, solved as the case
// asks (single loop, contact.equilibrium = "stable"), must converge at every point on two meshes (60 × 20
// and 90 × 30 half models), pass an instability on its way and say so (LoadPoint::escapes, the progress
// line), end every point on a stable state, and agree between the meshes where the response is smooth.
// Before the solver changes of commit efa3015 the 60 × 20 curve stopped at δz = 13.5 mm (Newton:
// residual 1.5e-4 after 24 iterations, after 6 cut-backs), where it now passes the instability.
// (Coarser meshes, 36 × 12 and 60 × 12, are unsuitable: their inflated state is already unstable, its
// tangent needing a shift of 0.1 and 0.01, an artefact of the long coarse elements.)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "tirefem/analysis/static_contact_run.hpp"
#include "tirefem/report/shell_results.hpp"
#include "tirefem/tyre/ply_stiffness.hpp"

namespace tirefem::verification {
namespace {

const Case& wrinkling_case() {
  static const Case c =
      read_case(std::filesystem::path(TIREFEM_SOURCE_DIR) / "tests/verification/data/wrinkling_tyre.toml");
  return c;
}

// The most compressed point of the belt (outer) face in the crown zone, and the face-wrinkling estimate
// there: σ_w = 0.5 (E_f E_c G_c)^(1/3) (a stiff face on a soft, thick core), E_f the face's modulus along
// the compression (A = the face's membrane stiffness, t its thickness), as a resultant σ_w · t.
struct CrownCompression {
  double resultant_N_mm = 0.0;  // smallest principal resultant (< 0: compression)
  double s_mm = 0.0, phi_deg = 0.0;
  double wrinkling_N_mm = 0.0;  // the estimate, as a (positive) resultant
};

CrownCompression crown_compression(const TyreMesh& tm, const Case& c, const Eigen::VectorXd& displacement) {
  const std::vector<ElementResult> results =
      evaluate_element_results(tm, c.tyre, displacement, Kinematics::nonlinear);
  CrownCompression out;
  out.resultant_N_mm = std::numeric_limits<double>::infinity();
  const ShellMesh& m = tm.mesh;
  for (int j = 0; j < m.v_elements(); ++j)
    for (int i = 0; i < m.u_elements(); ++i) {
      const int e = m.element_index(i, j);
      if (tm.element_zone[e] != 0) continue;  // the crown
      const Eigen::Vector3d& n = results[e].state.outer_resultant;  // [N11, N22, N12]
      const double centre = 0.5 * (n[0] + n[1]), radius = std::hypot(0.5 * (n[0] - n[1]), n[2]);
      if (centre - radius >= out.resultant_N_mm) continue;
      out.resultant_N_mm = centre - radius;
      out.s_mm = tm.element_s[e];
      out.phi_deg = std::remainder(0.5 * (m.v_values[j] + m.v_values[j + 1]), 2 * kPi) * 180.0 / kPi;
      // Direction of the smallest principal resultant, and the face's stiffness along it in uniaxial
      // stress: 1 / (mᵀ A⁻¹ m), m = [c², s², cs] (engineering shear in the strain vector).
      const double theta = 0.5 * std::atan2(2 * n[2], n[0] - n[1]) + kPi / 2;
      const double co = std::cos(theta), si = std::sin(theta);
      const Eigen::Vector3d dir(co * co, si * si, co * si);
      const double stiffness = 1.0 / dir.dot(tm.sections[e].outer_face.inverse() * dir);  // E_f t, N/mm
      double thickness = 0.0;
      for (const Ply& p : c.tyre.zones[0].outer.plies) thickness += p.thickness;
      const double Ef = stiffness / thickness;
      const Zone& z = c.tyre.zones[0];
      out.wrinkling_N_mm = 0.5 * std::cbrt(Ef * z.core_normal_modulus * z.core_shear_modulus) * thickness;
    }
  return out;
}

struct MeshRun {
  std::string label;
  StaticContactResult result;
  CrownCompression final_compression;
  double seconds = 0.0;
};

MeshRun run_on(int circumferential, int meridional) {
  const Case& c = wrinkling_case();
  MeshRun run;
  run.label = std::to_string(circumferential) + " x " + std::to_string(meridional);
  MeshSettings mesh = c.mesh;
  mesh.circumferential_elements = circumferential;
  mesh.meridional_elements = meridional;
  const TyreMesh tm = build_tyre_mesh(c.tyre, mesh);
  const Stopwatch clock;
  run.result = run_load_curve(tm, c.tyre, c.inflation, c.contact, c.load_curves.front());
  run.seconds = clock.seconds();
  if (run.result.completed) run.final_compression = crown_compression(tm, c, run.result.final_state.displacement);
  const StaticContactResult& r = run.result;
  std::printf("  %s half model (%.1f s; %d Newton iterations, %d factorisations, %d cut-backs):\n",
              run.label.c_str(), run.seconds, r.counters.newton_iterations, r.counters.factorizations,
              r.counters.cutbacks);
  for (const LoadPoint& p : r.points)
    std::printf("    δz %5.1f mm: Qz %7.1f N, pmax %.3f MPa, %2d Newton iterations, %2d factorisations, %d "
                "increments%s%s\n",
                p.deflection_mm, p.patch.Qz_N, p.patch.max_pressure_MPa, p.newton_iterations, p.factorizations,
                p.increments, stable(p.tangent_shift) ? "" : ", UNSTABLE",
                p.escapes ? fmt::format(", passed {} instabilities (largest shift {:.0e})", p.escapes,
                                        p.escaped_shift)
                                .c_str()
                          : "");
  if (!r.completed) std::printf("    stopped: %s\n", r.failure.c_str());
  const CrownCompression& cc = run.final_compression;
  std::printf("    final state: belt face most compressed at s %.1f mm, φ %.1f°: %.1f N/mm; face-wrinkling "
              "estimate 0.5 (E_f E_c G_c)^(1/3) t = %.1f N/mm\n",
              cc.s_mm, cc.phi_deg, cc.resultant_N_mm, cc.wrinkling_N_mm);
  return run;
}

int escapes(const StaticContactResult& r) {
  int n = 0;
  for (const LoadPoint& p : r.points) n += p.escapes;
  return n;
}

TEST(WrinklingTyre, LoadCurveConvergesAtEveryPointOnTwoMeshes) {
  const LoadCurveStudy& study = wrinkling_case().load_curves.front();
  ASSERT_EQ(wrinkling_case().contact.equilibrium, ContactSettings::Equilibrium::stable);
  const std::vector<MeshRun> runs = {run_on(60, 20), run_on(90, 30)};
  for (const MeshRun& run : runs) {
    const StaticContactResult& r = run.result;
    ASSERT_TRUE(r.completed) << run.label << ": " << r.failure;
    ASSERT_EQ(static_cast<int>(r.points.size()), study.points + 1) << run.label << ": every point converged";
    for (const LoadPoint& p : r.points)
      EXPECT_TRUE(stable(p.tangent_shift)) << run.label << ", δz " << p.deflection_mm
                                           << ": the stable-equilibrium solver ends on a stable state";
    EXPECT_GT(escapes(r), 0) << run.label << ": the path passes an instability and says so";
    // At the end of the curve the belt face is compressed beyond the face-wrinkling estimate (observed at
    // 40 mm: −24.3 and −18.2 N/mm against 11.4 N/mm, at the crown edge s ≈ 57 mm, φ ≈ ±47°, where the
    // loaded tyre bulges beside the patch; under the patch itself the face stays in hoop tension).
    EXPECT_LT(run.final_compression.resultant_N_mm, -run.final_compression.wrinkling_N_mm) << run.label;
  }
  // Mesh convergence where the response is smooth: before the first instability passed on either mesh
  // the two meshes' Qz agree within 8 % (observed ≤ 5.7 %, at 2 mm, falling to 4 % at 12 mm and 2.4 % at
  // 40 mm). Qz converges at about first order on these meshes (ContactMeshConvergence: the example tyre's
  // Qz(20 mm) differs by 10 % between 48 × 12 and 96 × 24), so 60 × 20 against 90 × 30 cannot agree closer.
  const StaticContactResult &coarse = runs[0].result, &fine = runs[1].result;
  double first_escape = 1e9;
  for (const StaticContactResult* r : {&coarse, &fine})
    for (const LoadPoint& p : r->points)
      if (p.escapes) first_escape = std::min(first_escape, p.deflection_mm);
  double largest = 0.0;
  for (std::size_t k = 1; k < coarse.points.size() && k < fine.points.size(); ++k) {
    const double d = coarse.points[k].deflection_mm;
    ASSERT_NEAR(d, fine.points[k].deflection_mm, 1e-9);
    const double rel = std::abs(coarse.points[k].patch.Qz_N - fine.points[k].patch.Qz_N) / fine.points[k].patch.Qz_N;
    std::printf("  δz %5.1f mm: Qz %s %.1f N, %s %.1f N, difference %.2f %%%s\n", d, runs[0].label.c_str(),
                coarse.points[k].patch.Qz_N, runs[1].label.c_str(), fine.points[k].patch.Qz_N, 100 * rel,
                d < first_escape ? "" : " (beyond the first instability)");
    if (d < first_escape) {
      largest = std::max(largest, rel);
      EXPECT_LT(rel, 0.08) << "Qz at δz " << d << " mm, " << runs[0].label << " against " << runs[1].label;
    }
  }
  std::printf("  smooth part (δz < %.1f mm): largest Qz difference between the meshes %.2f %%\n", first_escape,
              100 * largest);
}

// The message of a point lost to an instability (contact_iteration.cpp): on the 60 × 20 mesh the point
// after δz = 12 mm leaves an unstable equilibrium and needs 15 Newton iterations to reach the stable state
// beyond it (observed; the points before it at most 9). Given 12 iterations and no cut-back, that point
// fails, and its message must say that the tyre lost its stability on the way, not ask for more
// iterations, and name the README's section on the mesh.
TEST(WrinklingTyre, APointLostToAnInstabilityIsReportedAsSuch) {
  const Case& c = wrinkling_case();
  const LoadCurveStudy& study = c.load_curves.front();
  MeshSettings mesh = c.mesh;
  mesh.circumferential_elements = 60;
  mesh.meridional_elements = 20;
  const TyreMesh tm = build_tyre_mesh(c.tyre, mesh);
  ContactSettings settings = c.contact;
  settings.max_newton_iterations = 12;
  StaticContactResult result = empty_result(tm, settings, study);
  StaticContactRun run(tm, c.tyre, c.inflation, settings, study.support, Kinematics::nonlinear,
                       study.deflection_from, result, {}, nullptr);
  const double step = study.max_deflection / study.points;
  double failed_at = -1.0;
  for (int k = 1; k <= study.points && failed_at < 0; ++k)
    if (!run.solve_at(k * step, /*max_cutbacks=*/0)) failed_at = k * step;
  std::printf("  first point lost: δz %.1f mm: %s\n", failed_at, result.failure.c_str());
  ASSERT_GT(failed_at, 0.0) << "the points after the instability need more than 12 Newton iterations";
  EXPECT_NE(result.failure.find("the tyre lost its stability on the way"), std::string::npos) << result.failure;
  EXPECT_NE(result.failure.find("\"How fine a mesh\""), std::string::npos) << result.failure;
  EXPECT_EQ(result.failure.find("max_newton_iterations"), std::string::npos) << result.failure;
}

}  // namespace
}  // namespace tirefem::verification
