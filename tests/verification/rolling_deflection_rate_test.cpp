// The derivative of a rolling state in the support's deflection, du/dδz, which holding the load uses to
// step δz (RollingModel::hold_load): one linear solve with the state's exact tangent, K du/dδz = −∂R/∂δz.
// Checked against converged states at δz ± Δ on a coarse full model (40 × 12 per half, planar tread shear,
// 3000 N, μ = 0.7), in a traction state and a cornering one with sliding zones:
// - dQz/dδz along it against the central difference of the converged states' Qz (Δ = 0.05 mm): the
//   difference quotient differs from the derivative by the curvature of Qz(δz) (O(Δ²)) and by the points
//   entering contact or changing between stick and slip within ±Δ: 1% (observed 4e-4 and 2e-3).
// - The state at δz + Δ predicted along it, u + Δ du/dδz, against the converged one: the error is second
//   order in Δ where the stick/slip plan does not change; 5% of the change u(δz + Δ) − u(δz) (observed
//   1.5e-3 and 1.9e-2; it falls with Δ: at 0.002 mm 1.4e-4 and 2.9e-4). A ∂R/∂δz by differences over
//   0.01 mm instead of 1e-5 fails both (dQz/dδz 12% low, the prediction 15% off).
// The derivative in the slip, du/dt for (axle height / Rk, tan α, γ) moving along a direction
// (RollingModel::slip_rate; free rolling's secant steps on Rk are predicted along it), checked the same
// way in the same states against converged states at t = ±1 (κ ± 0.00025, α ± 0.025°): d(Fx, Fy)/dt
// against the central difference of the converged states' forces, 2% of its size (observed 1.9e-3 and
// 7.6e-3); the state at t = 1 predicted along it, u + du/dt, to 5% of the change (observed 6.1e-3 and
// 1.5e-2). Both fall with the step (at κ ± 0.001, α ± 0.1°: 3.6e-3 and 1.7e-2; 3.4e-2 and 4.3e-2): the
// points that change between stick and slip within ±Δ.
// Also the rolling start shared by studies at one load (RollingStart): a model that adopts its states
// solves a state as one that found free rolling itself (1e-6 relative); a start solved with another
// friction is refused.
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include "contact_support.hpp"
#include "tirefem/analysis/rolling.hpp"
#include "tirefem/analysis/rolling_model.hpp"

namespace tirefem::verification {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

RollingStudy rate_study() {
  RollingStudy s;
  s.name = "rate";
  s.target_load = 3000.0;
  s.friction = 0.7;
  s.tread_shear = RollingStudy::TreadShear::planar;
  return s;
}

ContactSettings rate_settings() {
  ContactSettings s = test_contact_settings(ContactSettings::Iteration::single_loop);
  s.residual_tolerance = 1e-10;
  return s;
}

const TyreMesh& full_tyre() {
  static const TyreMesh tm = build_tyre_mesh(example_case().tyre, coarse_mesh(40, 12, false));
  return tm;
}

const RollingStart& start() {
  static const RollingStart s =
      solve_rolling_start(full_tyre(), example_case().tyre, example_case().inflation, rate_settings(), rate_study());
  return s;
}

// The model of the study at the start's footprint, with the start's states.
struct Model {
  RollingResult result;
  std::unique_ptr<RollingModel> model;
  FrictionLaw law;  // Coulomb with the study's friction
  Model() {
    law.friction = rate_study().friction;
    const Case& c = example_case();
    result.footprint = start().footprint;
    result.deflection_mm = result.footprint.final_state.deflection_mm;
    result.axle_z = full_tyre().axis_z;
    result.loaded_radius_mm = result.axle_z - result.deflection_mm;
    result.effective_rolling_radius_mm = start().effective_rolling_radius_mm;
    model = std::make_unique<RollingModel>(full_tyre(), c.tyre, c.inflation, rate_settings(), rate_study(), result);
    model->adopt(start().states);
  }
};

struct RateCase {
  const char* name;
  double slip;
  double slip_angle_deg;
};

class RollingDeflectionRate : public ::testing::TestWithParam<RateCase> {};

TEST_P(RollingDeflectionRate, PredictsTheStatesAtNearbyDeflections) {
  ASSERT_TRUE(start().footprint.completed);
  ASSERT_TRUE(start().free.converged);
  const RateCase& rc = GetParam();
  Model m;
  RollingModel& model = *m.model;
  const FrictionLaw& law = m.law;
  const WheelSlip slip{*start().effective_rolling_radius_mm / (1.0 + rc.slip), rc.slip_angle_deg * kDegree, 0.0};
  const double d0 = model.deflection(), step = 0.05;
  const RollingModel::Solved at = model.solve(law, slip);
  ASSERT_TRUE(at.converged) << at.failure;
  Eigen::VectorXd rate;
  double stiffness = 0.0;
  ASSERT_TRUE(model.deflection_rate(at.u, rate, stiffness));
  EXPECT_EQ(model.deflection(), d0);
  model.set_deflection(d0 + step);
  const RollingModel::Solved above = model.solve(law, slip, true);
  model.set_deflection(d0 - step);
  const RollingModel::Solved below = model.solve(law, slip, true);
  ASSERT_TRUE(above.converged && below.converged);
  const double quotient = (above.figures.Qz_N - below.figures.Qz_N) / (2.0 * step);
  const double prediction_error = (above.u - at.u - step * rate).norm() / (above.u - at.u).norm();
  std::printf("  %s: Qz %.1f N, stick %.0f%%; dQz/dδz %.2f N/mm, central difference ±%.2f mm %.2f N/mm (%+.1e); "
              "state at δz + %.2f mm predicted to %.1e of its change\n",
              rc.name, at.figures.Qz_N, 100 * at.figures.stick_area_fraction, stiffness, step, quotient,
              stiffness / quotient - 1.0, step, prediction_error);
  EXPECT_NEAR(stiffness, quotient, 0.01 * quotient);
  EXPECT_LT(prediction_error, 0.05);
}

INSTANTIATE_TEST_SUITE_P(States, RollingDeflectionRate,
                         ::testing::Values(RateCase{"traction", 0.02, 0.0}, RateCase{"cornering", 0.0, 3.0}),
                         [](const auto& info) { return std::string(info.param.name); });

struct SlipRateCase {
  const char* name;
  double slip, slip_angle_deg;      // the state
  double slip_step, angle_step_deg;  // t = 1
};

class RollingSlipRate : public ::testing::TestWithParam<SlipRateCase> {};

TEST_P(RollingSlipRate, PredictsTheStatesAtNearbySlips) {
  ASSERT_TRUE(start().free.converged);
  const SlipRateCase& rc = GetParam();
  Model m;
  RollingModel& model = *m.model;
  const FrictionLaw& law = m.law;
  const double re = *start().effective_rolling_radius_mm;
  const auto slip_at = [&](double t) {
    return WheelSlip{re / (1.0 + rc.slip + t * rc.slip_step), (rc.slip_angle_deg + t * rc.angle_step_deg) * kDegree, 0.0};
  };
  const RollingModel::Solved at = model.solve(law, slip_at(0.0));
  ASSERT_TRUE(at.converged) << at.failure;
  Eigen::VectorXd rate;
  Eigen::Vector2d force_rate;
  ASSERT_TRUE(model.slip_rate(at.u, slip_at(0.0), slip_at(1.0), rate, force_rate));
  const RollingModel::Solved above = model.solve(law, slip_at(1.0), true);
  const RollingModel::Solved below = model.solve(law, slip_at(-1.0));
  ASSERT_TRUE(above.converged && below.converged);
  const Eigen::Vector2d quotient(0.5 * (above.figures.Fx_N - below.figures.Fx_N),
                                 0.5 * (above.figures.Fy_N - below.figures.Fy_N));
  const double force_error = (force_rate - quotient).norm() / quotient.norm();
  const double prediction_error = (above.u - at.u - rate).norm() / (above.u - at.u).norm();
  std::printf("  %s: Fx %.1f N, Fy %.1f N, stick %.0f%%; d(Fx, Fy)/dt (%.2f, %.2f) N, central difference (%.2f, %.2f) N "
              "(%.1e); state at t = 1 predicted to %.1e of its change\n",
              rc.name, at.figures.Fx_N, at.figures.Fy_N, 100 * at.figures.stick_area_fraction, force_rate.x(),
              force_rate.y(), quotient.x(), quotient.y(), force_error, prediction_error);
  EXPECT_LT(force_error, 0.02);
  EXPECT_LT(prediction_error, 0.05);
}

INSTANTIATE_TEST_SUITE_P(States, RollingSlipRate,
                         ::testing::Values(SlipRateCase{"traction", 0.02, 0.0, 0.00025, 0.0},
                                           SlipRateCase{"cornering", 0.0, 3.0, 0.0, 0.025}),
                         [](const auto& info) { return std::string(info.param.name); });

// Two models of the study: one finds free rolling itself, the other adopts the shared start's states.
// Both then solve the same traction state: the same answer to the Newton tolerance.
TEST(RollingStart, AStudyFromTheSharedStartSolvesAsOneThatFoundFreeRollingItself) {
  ASSERT_TRUE(start().free.converged);
  const Case& c = example_case();
  RollingStudy own = rate_study();
  own.states.push_back({});  // free rolling
  RollingStateSpec traction;
  traction.kind = RollingStateSpec::Kind::given_slip;
  traction.slip = 0.02;
  own.states.push_back(traction);
  const RollingResult alone = run_rolling(full_tyre(), c.tyre, c.inflation, rate_settings(), own);
  const RollingResult shared =
      run_rolling(full_tyre(), c.tyre, c.inflation, rate_settings(), own, {}, nullptr, nullptr, {}, nullptr, &start());
  ASSERT_TRUE(alone.completed) << alone.failure;
  ASSERT_TRUE(shared.completed) << shared.failure;
  ASSERT_EQ(alone.states.size(), 2u);
  ASSERT_EQ(shared.states.size(), 2u);
  EXPECT_NEAR(*shared.effective_rolling_radius_mm, *alone.effective_rolling_radius_mm, 1e-9);
  EXPECT_NEAR(shared.deflection_mm, alone.deflection_mm, 1e-9);
  for (std::size_t i = 0; i < 2; ++i) {
    const RollingFigures& a = alone.states[i].figures;
    const RollingFigures& b = shared.states[i].figures;
    EXPECT_NEAR(b.Qy_N, a.Qy_N, 1e-6 * a.Qz_N) << alone.states[i].name;
    EXPECT_NEAR(b.Qz_N, a.Qz_N, 1e-6 * a.Qz_N) << alone.states[i].name;
    EXPECT_NEAR(b.Mx_Nmm, a.Mx_Nmm, 1e-6 * std::abs(a.Mx_Nmm) + 1e-3) << alone.states[i].name;
  }
  EXPECT_NEAR(shared.states[1].figures.Qy_N, alone.states[1].figures.Qy_N, 1e-6 * std::abs(alone.states[1].figures.Qy_N));
  RollingStudy slippery = own;
  slippery.friction = 0.5;
  EXPECT_THROW(run_rolling(full_tyre(), c.tyre, c.inflation, rate_settings(), slippery, {}, nullptr, nullptr, {}, nullptr,
                           &start()),
               std::invalid_argument);
}

}  // namespace
}  // namespace tirefem::verification
