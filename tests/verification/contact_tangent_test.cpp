// Consistency of the Winkler contact form (MODEL.md §4, eqs. 6–11): its tangent is the exact derivative
// of its residual, and the supports' penetration gradients and hessians are the exact derivatives of the
// penetration. Reference: central finite differences, whose truncation error is O(h²·g''') and whose
// round-off is O(ε·|r|/h). With h = 1e-5 mm on O(100 mm) coordinates and O(100 N) residuals both are below
// 1e-9 of the tangent's largest entry, so a relative error of 1e-6 is a clean pass/fail line: a missing
// or wrong term (e.g. the drum's curvature term kp g ∂²g, which is ≥ 1e-3 of the tangent here, checked
// below) shows up a thousand times above it.
//
// Mesh: the tyre-like cylindrical patch of form_fd_support.hpp (tread touching z = 0 at φ = 0), 6 × 10
// elements, 3 × 3 tread points each, under a random displacement of ±1.5 mm on every DOF. In the
// single-loop (released) case the region {g > 0} changes with the displacement, so the random state is
// redrawn until no tread point lies within 1e-3 mm of g = 0 (a step of h cannot cross the kink); in the
// frozen case every frozen point carries kp g whatever its sign, and the frozen region includes points
// with g < 0 and leaves out some with g > 0.
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "form_fd_support.hpp"
#include "tirefem/forms/winkler_contact_form.hpp"
#include "tirefem/road/support_surface.hpp"

namespace tirefem::verification {
namespace {

constexpr double kStep = kFdStep;           // finite-difference step, mm
constexpr double kTolerance = kFdTolerance; // relative error of the tangent / derivatives
constexpr double kMargin = 1e-3;            // no tread point this close to g = 0 in the released case

// The contact form alone, assembled over all DOFs (nothing fixed).
using ContactOnly = SingleFormProblem<WinklerContactForm>;

ContactOnly contact_only(const ShellMesh& mesh, const RigidSurface& support, double deflection) {
  auto form = std::make_unique<WinklerContactForm>(mesh, patch_points(mesh), 1.3, support);
  form->set_deflection(deflection);
  return ContactOnly(mesh, std::move(form));
}

struct PenetrationRange {
  int inside = 0, outside = 0;
  double closest_to_zero = 1e300;
};

PenetrationRange penetrations(const WinklerContactForm& c, const Eigen::VectorXd& u) {
  PenetrationRange r;
  for (const TreadPointState& s : c.evaluate(u)) {
    (s.penetration > 0 ? r.inside : r.outside)++;
    r.closest_to_zero = std::min(r.closest_to_zero, std::abs(s.penetration));
  }
  return r;
}

// A random displacement (±1.5 mm on every DOF) with no tread point within kMargin of g = 0.
Eigen::VectorXd random_state(ContactOnly& c, int dofs, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  for (int attempt = 0; attempt < 200; ++attempt) {
    Eigen::VectorXd u(dofs);
    for (int i = 0; i < dofs; ++i) u[i] = uniform(rng);
    const PenetrationRange r = penetrations(*c.form, u);
    if (r.closest_to_zero > kMargin && r.inside > 20 && r.outside > 20) return u;
  }
  throw std::runtime_error("no random state away from g = 0 found");
}

void check_support(const char* label, const SupportSurface& support, double deflection, bool curved) {
  const SingleThread single_thread;
  const ShellMesh mesh = tyre_patch_mesh();
  ContactOnly c = contact_only(mesh, support, deflection);
  const Eigen::VectorXd u = random_state(c, mesh.dof_count(), 4711);
  const PenetrationRange range = penetrations(*c.form, u);

  // Single loop: Ωc = {g > 0} at the iterate.
  c.form->release_region();
  const Eigen::MatrixXd k = c.tangent(u);
  const double released = max_relative_error(fd_tangent(c, u), k);
  EXPECT_LT(released, kTolerance) << label << ", released region: tangent vs central differences";
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * k.cwiseAbs().maxCoeff())
      << label << ": the contact tangent must be symmetric";

  // Frozen region: every point with g > −1.5 mm except every 7th, so it contains points with g < 0 (which
  // then pull: kp g < 0) and misses some with g > 0.
  const std::vector<TreadPointState> states = c.form->evaluate(u);
  std::vector<char> region(states.size());
  int frozen_negative = 0, left_out_positive = 0;
  for (std::size_t q = 0; q < states.size(); ++q) {
    region[q] = states[q].penetration > -1.5 && q % 7 != 0;
    frozen_negative += region[q] && states[q].penetration < 0;
    left_out_positive += !region[q] && states[q].penetration > 0;
  }
  ASSERT_GT(frozen_negative, 0);
  ASSERT_GT(left_out_positive, 0);
  c.form->freeze_region(region);
  const Eigen::MatrixXd kf = c.tangent(u);
  const double frozen = max_relative_error(fd_tangent(c, u), kf);
  EXPECT_LT(frozen, kTolerance) << label << ", frozen region: tangent vs central differences";

  // How much the support's curvature term contributes (zero on the plane).
  WithoutCurvature flat(support);
  ContactOnly c0 = contact_only(mesh, flat, deflection);
  c0.form->freeze_region(region);
  const double curvature_share = max_relative_error(c0.tangent(u), kf);
  if (curved)
    EXPECT_GT(curvature_share, 1e3 * kTolerance)
        << label << ": the curvature term must be large enough for the check to see it";
  else
    EXPECT_EQ(curvature_share, 0.0) << label;

  std::printf("  %s: %d points in contact, %d out (closest |g| %.2e mm); tangent error released %.2e, "
              "frozen %.2e (%d frozen with g < 0, %d left out with g > 0); curvature term %.2e of the tangent\n",
              label, range.inside, range.outside, range.closest_to_zero, released, frozen, frozen_negative,
              left_out_positive, curvature_share);
}

TEST(ContactTangent, PlaneMatchesFiniteDifferences) {
  RoadPlane plane;
  check_support("plane", plane, 4.0, false);
}

TEST(ContactTangent, DrumMatchesFiniteDifferences) {
  TestDrum drum(915.0);
  check_support("drum R 915", drum, 6.0, true);
}

std::vector<SupportDescription::Term> road_terms() {
  // Cambered across (x²), falling away along (−y²), skewed (x y, x y³): every second derivative non-zero.
  return {{2e-3, 2, 0}, {-1e-3, 0, 2}, {5e-4, 1, 1}, {1e-7, 1, 3}};
}

TEST(ContactTangent, PolynomialRoadMatchesFiniteDifferences) {
  PolynomialRoad road(road_terms());
  check_support("polynomial road", road, 4.0, true);
}

// g, ∂g/∂x and ∂²g/∂x² of the supports against central differences at random points around the patch.
void check_penetration_derivatives(const char* label, const SupportSurface& s, double deflection) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> ux(-60, 60), uy(-120, 120), uz(-10, 25);
  double worst_gradient = 0.0, worst_hessian = 0.0;
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d x(ux(rng), uy(rng), uz(rng));
    const Penetration p = s.penetration(x, deflection);
    Eigen::Vector3d grad;
    Eigen::Matrix3d hess;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d a = x, b = x;
      a[i] += kStep, b[i] -= kStep;
      const Penetration pa = s.penetration(a, deflection), pb = s.penetration(b, deflection);
      grad[i] = (pa.value - pb.value) / (2 * kStep);
      hess.col(i) = (pa.gradient - pb.gradient) / (2 * kStep);
    }
    worst_gradient = std::max(worst_gradient, (grad - p.gradient).norm() / p.gradient.norm());
    const double scale = std::max(p.hessian.norm(), 1e-300);
    worst_hessian = std::max(worst_hessian, p.hessian.norm() == 0.0 ? hess.norm() : (hess - p.hessian).norm() / scale);
    // Moving the support up by δz is moving the point down by δz: ∂g/∂δz = −∂g/∂z.
    const double dd = (s.penetration(x, deflection + kStep).value - s.penetration(x, deflection - kStep).value) /
                      (2 * kStep);
    EXPECT_NEAR(dd, -p.gradient.z(), 1e-8) << label << ": ∂g/∂δz must equal −∂g/∂z";
  }
  EXPECT_LT(worst_gradient, kTolerance) << label << ": gradient vs central differences of g";
  EXPECT_LT(worst_hessian, kTolerance) << label << ": hessian vs central differences of the gradient";
  std::printf("  %s: penetration gradient error %.2e, hessian error %.2e\n", label, worst_gradient, worst_hessian);
}

TEST(ContactTangent, SupportPenetrationDerivatives) {
  RoadPlane plane;
  TestDrum drum(915.0);
  PolynomialRoad road(road_terms());
  check_penetration_derivatives("plane", plane, 3.0);
  check_penetration_derivatives("drum R 915", drum, 3.0);
  check_penetration_derivatives("polynomial road", road, 3.0);
  // The drum's value is the exact radial distance: a point 2 mm below the top of the drum at δz = 3.
  EXPECT_NEAR(drum.penetration(Eigen::Vector3d(5.0, 0.0, 1.0), 3.0).value, 2.0, 1e-12);
  const double y = 100.0, top = 3.0 - 915.0 + std::sqrt(915.0 * 915.0 - y * y);
  EXPECT_NEAR(drum.penetration(Eigen::Vector3d(0.0, y, top), 3.0).value, 0.0, 1e-9);
  EXPECT_NEAR(drum.height(0.0, y, 3.0), top, 1e-12);
  EXPECT_NEAR(road.penetration(Eigen::Vector3d(10.0, 20.0, 0.5), 3.0).value,
              2e-3 * 100 - 1e-3 * 400 + 5e-4 * 200 + 1e-7 * 10 * 8000 + 3.0 - 0.5, 1e-12);
}

}  // namespace
}  // namespace tirefem::verification
