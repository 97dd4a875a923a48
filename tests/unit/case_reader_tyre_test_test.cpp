// The case reader's [[tyre_test]] studies (the virtual flat-track rig): a full study reads back, omitted keys
// take the defaults of issue 12 (0.5, 1, 1.5 × FNOMIN; 15 κ and 15 α points, Fz held), and every input
// error names the field.
#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"
#include "tirefem/analysis/tyre_test.hpp"
#include "tirefem/case/case_reader.hpp"

namespace tirefem {
namespace {

using case_test::error_of;
using case_test::tyre_with;

const std::string kFullMesh =
    "mesh = { circumferential_elements = 64, meridional_elements = 12, half_model = false }\n";

std::string rig_with(const std::string& extra) {
  return tyre_with("[[tyre_test]]\nname = \"rig\"\n" + kFullMesh + extra);
}

TEST(CaseReaderTyreTest, ReadsAFullStudy) {
  const Case c = parse_case(rig_with("nominal_load = 4000.0\n"
                                     "loads = [0.25, 1.0, 2.0]\n"
                                     "load_tolerance = 2e-3\n"
                                     "friction = 0.9\n"
                                     "slip_sweep = { from = -0.2, to = 0.1, points = 7 }\n"
                                     "angle_sweep = { from = -8.0, to = 10.0, points = 9 }\n"
                                     "cambers = [-3.0, 3.0]\n"
                                     "combined = { slips = [-0.05, 0.05], slip_angles = [2.0, 6.0] }\n"
                                     "vertical = { max_deflection = 30.0, points = 6 }\n"),
                            "case.toml");
  ASSERT_EQ(c.tyre_tests.size(), 1u);
  const TyreTestStudy& s = c.tyre_tests[0];
  EXPECT_EQ(s.name, "rig");
  EXPECT_EQ(s.nominal_load, 4000.0);
  EXPECT_EQ(s.load_factors, (std::vector<double>{0.25, 1.0, 2.0}));
  EXPECT_EQ(s.load_tolerance, 2e-3);
  EXPECT_EQ(s.friction, 0.9);
  EXPECT_EQ(s.slip_sweep.from, -0.2);
  EXPECT_EQ(s.slip_sweep.to, 0.1);
  EXPECT_EQ(s.slip_sweep.points, 7);
  EXPECT_TRUE(s.slip_sweep.hold_load);
  EXPECT_EQ(s.angle_sweep.from, -8.0);
  EXPECT_EQ(s.angle_sweep.to, 10.0);
  EXPECT_EQ(s.angle_sweep.points, 9);
  EXPECT_TRUE(s.angle_sweep.hold_load);
  EXPECT_EQ(s.cambers_deg, (std::vector<double>{-3.0, 3.0}));
  ASSERT_TRUE(s.combined);
  EXPECT_EQ(s.combined->slips, (std::vector<double>{-0.05, 0.05}));
  EXPECT_EQ(s.combined->slip_angles_deg, (std::vector<double>{2.0, 6.0}));
  EXPECT_TRUE(s.combined->hold_load);
  EXPECT_EQ(tyre_test_points(s), 3 * (2 + 2 + 7 + 9 + 4));
  EXPECT_EQ(s.vertical_max_deflection, 30.0);
  EXPECT_EQ(s.vertical_points, 6);
  ASSERT_TRUE(s.mesh);
  EXPECT_FALSE(s.mesh->half_model);
  EXPECT_EQ(s.mesh->circumferential_elements, 64);
}

TEST(CaseReaderTyreTest, DefaultsAreTheIssuesRig) {
  const TyreTestStudy s = parse_case(rig_with(""), "case.toml").tyre_tests.at(0);
  EXPECT_EQ(s.nominal_load, 3700.0);
  EXPECT_EQ(s.load_factors, (std::vector<double>{0.5, 1.0, 1.5}));
  EXPECT_EQ(s.slip_sweep.points, 15);
  EXPECT_EQ(s.angle_sweep.points, 15);
  EXPECT_EQ(s.friction, 0.7);
  EXPECT_TRUE(s.cambers_deg.empty());
  EXPECT_FALSE(s.combined);
  EXPECT_EQ(s.vertical_points, 10);
}

TEST(CaseReaderTyreTest, ErrorsNameTheField) {
  // The example's case mesh is the half model: a rig without its own full mesh cannot roll at an angle.
  EXPECT_NE(error_of(tyre_with("[[tyre_test]]\nname = \"rig\"\n")).find("tyre_test[0]: a tyre test needs the full model"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("loads = [1.0, 0.5]\n")).find("tyre_test[0].loads[1]: must be greater than the load before"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("loads = [-1.0]\n")).find("tyre_test[0].loads[0]"), std::string::npos);
  EXPECT_NE(error_of(rig_with("loads = []\n")).find("tyre_test[0].loads: must list at least one load"), std::string::npos);
  EXPECT_NE(error_of(rig_with("nominal_load = 0.0\n")).find("tyre_test[0].nominal_load"), std::string::npos);
  EXPECT_NE(error_of(rig_with("slip_sweep = { form = 0.1 }\n")).find("tyre_test[0].slip_sweep.form: unknown key"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("slip_sweep = { points = 2 }\n")).find("tyre_test[0].slip_sweep.points"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("angle_sweep = { from = 5.0, to = -5.0 }\n")).find("tyre_test[0].angle_sweep.to"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("cambers = [30.0]\n")).find("tyre_test[0].cambers[0]"), std::string::npos);
  EXPECT_NE(error_of(rig_with("vertical = { points = 0 }\n")).find("tyre_test[0].vertical.points"), std::string::npos);
  EXPECT_NE(error_of(rig_with("combined = { slips = [0.0, 0.05], slip_angles = [2.0, 4.0] }\n"))
                .find("tyre_test[0].combined.slips[0]: must not be 0"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("combined = { slips = [-0.05, 0.05], slip_angles = [4.0] }\n"))
                .find("tyre_test[0].combined.slip_angles: must list at least two"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("combined = { slips = [-0.05, 0.05], slip_angles = [2.0, 4.0], hold = \"load\" }\n"))
                .find("tyre_test[0].combined.hold: unknown key"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("combined = { slips = [-0.05, 0.05] }\n")).find("tyre_test[0].combined.slip_angles"),
            std::string::npos);
  EXPECT_NE(error_of(rig_with("friction = -0.1\n")).find("tyre_test[0].friction"), std::string::npos);
  EXPECT_NE(error_of(rig_with("sweep = {}\n")).find("tyre_test[0].sweep: unknown key"), std::string::npos);
  // Study names are unique across all studies.
  EXPECT_NE(error_of(rig_with("") + "[[tyre_test]]\nname = \"rig\"\n" + kFullMesh).find("tyre_test[1].name"),
            std::string::npos);
}

}  // namespace
}  // namespace tirefem
