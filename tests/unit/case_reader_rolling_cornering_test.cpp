// The case reader's [[rolling]] studies, continued: a study's own mesh, states that hold the load, the sweep's
// hold, and the cornering keys (slip angle, camber, the α sweep and the combined grid), each refusal naming
// its field.
#include "tirefem/case/case_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"

namespace tirefem {
namespace {

using case_test::error_of;
using case_test::rolling_with;
using case_test::state;
using case_test::tyre_with;

TEST(CaseReaderRollingMesh, OwnMeshInheritsTheCaseMesh) {
  const Case c = parse_case(rolling_with("mesh = { circumferential_elements = 80 }"), "case.toml");
  ASSERT_TRUE(c.rolling[0].mesh.has_value());
  EXPECT_EQ(c.rolling[0].mesh->circumferential_elements, 80);
  EXPECT_EQ(c.rolling[0].mesh->meridional_elements, c.mesh.meridional_elements);
  EXPECT_EQ(c.rolling[0].mesh->circumferential_refinement, c.mesh.circumferential_refinement);
  EXPECT_FALSE(parse_case(rolling_with(""), "case.toml").rolling[0].mesh.has_value());
  EXPECT_CONTAINS(error_of(rolling_with("mesh = { circumferential_elements = 2 }")),
                  "rolling[0].mesh.circumferential_elements: must be ≥ 3 (got 2)");
  EXPECT_CONTAINS(error_of(rolling_with("mesh = { circumferential_element = 2 }")),
                  "rolling[0].mesh.circumferential_element: unknown key");
}

TEST(CaseReaderRolling, AStateMayHoldTheLoad) {
  const Case c = parse_case(rolling_with("mesh = { half_model = false }",
                                         "states = [{ state = \"free\", camber = 2.0, hold = \"load\" }, { state = "
                                         "\"given_slip\", slip = 0.02, hold = \"deflection\" }, { state = \"free\" }]"),
                            "case.toml");
  ASSERT_EQ(c.rolling[0].states.size(), 3u);
  EXPECT_TRUE(c.rolling[0].states[0].hold_load);
  EXPECT_FALSE(c.rolling[0].states[1].hold_load);
  EXPECT_FALSE(c.rolling[0].states[2].hold_load);
  EXPECT_CONTAINS(error_of(state("{ state = \"given_slip\", slip = 0.02, hold = \"axle\" }")),
                  "rolling[0].states[0].hold");
  EXPECT_CONTAINS(error_of(state("{ state = \"full_slip\", hold = \"load\" }")),
                  "rolling[0].states[0].hold: not allowed in a \"full_slip\" state (it takes state, name and wheel)");
}

TEST(CaseReaderRollingSweep, HoldIsDeflectionOrLoad) {
  EXPECT_FALSE(parse_case(rolling_with("sweep = { points = 3 }"), "case.toml").rolling[0].sweep->hold_load);
  EXPECT_TRUE(parse_case(rolling_with("sweep = { points = 3, hold = \"load\" }"), "case.toml").rolling[0].sweep->hold_load);
  EXPECT_FALSE(
      parse_case(rolling_with("sweep = { hold = \"deflection\" }"), "case.toml").rolling[0].sweep->hold_load);
  const std::string e = error_of(rolling_with("sweep = { hold = \"axle\" }"));
  EXPECT_NE(e.find("rolling[0].sweep.hold"), std::string::npos) << e;
  EXPECT_NE(e.find("load"), std::string::npos) << e;
}

// Cornering (issue 11): slip angle and camber per state, the α sweep and the combined (κ, α) grid, read
// back; they need the full model (and camber a plane), each refusal naming its field.
TEST(CaseReaderRolling, ReadsCorneringStatesAndSweeps) {
  const Case c = parse_case(rolling_with(
      "mesh = { half_model = false }\n"
      "angle_sweep = { from = -6.0, to = 6.0, points = 7, hold = \"load\", slip = 0.01, camber = 1.5 }\n"
      "combined = { slips = [-0.05, 0.05], slip_angles = [2.0, 4.0] }\n",
      "states = [{ state = \"free\", slip_angle = 2.0 }, { state = \"given_slip\", slip = 0.02, slip_angle = -1.0, "
      "camber = 3.0 }]"), "case.toml");
  const RollingStudy& r = c.rolling.front();
  ASSERT_EQ(r.states.size(), 2u);
  EXPECT_EQ(r.states[0].slip_angle_deg, 2.0);
  EXPECT_EQ(r.states[0].name, "free_alpha_2");
  EXPECT_EQ(r.states[1].slip_angle_deg, -1.0);
  EXPECT_EQ(r.states[1].camber_deg, 3.0);
  EXPECT_EQ(r.states[1].name, "slip_0.02_alpha_-1_camber_3");
  ASSERT_TRUE(r.angle_sweep.has_value());
  EXPECT_EQ(r.angle_sweep->from, -6.0);
  EXPECT_EQ(r.angle_sweep->to, 6.0);
  EXPECT_EQ(r.angle_sweep->points, 7);
  EXPECT_TRUE(r.angle_sweep->hold_load);
  EXPECT_EQ(r.angle_sweep->slip, 0.01);
  EXPECT_EQ(r.angle_sweep->camber_deg, 1.5);
  EXPECT_TRUE(r.angle_sweep->mirror_negative_angles) << "mirrored where exact unless the case says not";
  const Case solved_both = parse_case(
      rolling_with("mesh = { half_model = false }\nangle_sweep = { from = -2.0, to = 2.0, points = 3, mirror = false }"),
      "case.toml");
  EXPECT_FALSE(solved_both.rolling.front().angle_sweep->mirror_negative_angles);
  ASSERT_TRUE(r.combined.has_value());
  EXPECT_EQ(r.combined->slips, (std::vector<double>{-0.05, 0.05}));
  EXPECT_EQ(r.combined->slip_angles_deg, (std::vector<double>{2.0, 4.0}));
  EXPECT_FALSE(r.tread_shear.has_value());
}

TEST(CaseReaderRolling, CorneringNeedsTheFullModelAndCamberAPlane) {
  EXPECT_CONTAINS(error_of(state("{ state = \"free\", slip_angle = 2.0 }")),
                  "rolling[0].states[0].slip_angle: needs the full model (bead to bead)");
  EXPECT_CONTAINS(error_of(rolling_with("angle_sweep = { from = -2.0, to = 2.0, points = 3 }")),
                  "rolling[0].angle_sweep: needs the full model");
  EXPECT_CONTAINS(error_of(tyre_with("[[rolling]]\nname = \"r\"\nsupport = { kind = \"drum\", diameter = 1830.0 }\n"
                                     "mesh = { half_model = false }\n"
                                     "states = [{ state = \"free\", camber = 2.0 }]\n")),
                  "rolling[0].states[0].camber: camber is supported on a plane support only");
  EXPECT_CONTAINS(error_of(rolling_with("mesh = { half_model = false }\ntread_shear = \"longitudinal\"",
                                        "states = [{ state = \"free\", slip_angle = 1.0 }]")),
                  "rolling[0].states[0].slip_angle: needs tread_shear = \"planar\"");
  EXPECT_CONTAINS(error_of(rolling_with("mesh = { half_model = false }", "states = [{ state = \"free\", slip_angle = 50.0 }]")),
                  "rolling[0].states[0].slip_angle: must be within ±45 degrees (got 50)");
  EXPECT_CONTAINS(error_of(rolling_with("mesh = { half_model = false }\nangle_sweep = { from = 2.0, to = 1.0 }")),
                  "rolling[0].angle_sweep.to: must be greater than from = 2 (got 1)");
  EXPECT_CONTAINS(error_of(rolling_with("mesh = { half_model = false }\ncombined = { slips = [], slip_angles = [1.0] }")),
                  "rolling[0].combined.slips: must list at least one slip κ");
  EXPECT_CONTAINS(error_of(rolling_with("mesh = { half_model = false }\nangle_sweep = { points = 3, mirror = 1 }")),
                  "rolling[0].angle_sweep.mirror");
  EXPECT_CONTAINS(error_of(rolling_with("tread_shear = \"lateral\"")),
                  "rolling[0].tread_shear: must be \"longitudinal\" or \"planar\"");
}
}  // namespace
}  // namespace tirefem
