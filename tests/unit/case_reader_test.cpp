// The case reader: the example case reads back with the sheet's values, and every kind of input error is
// reported with the file, the line, the full field path and what was expected.
#include "tirefem/case/case_reader.hpp"

#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"
#include "tirefem/element/section.hpp"
#include "tirefem/tyre/meridian_profile.hpp"
#include "tirefem/tyre/tyre_mesh.hpp"

namespace tirefem {
namespace {

using namespace case_test;

TEST(CaseReader, ReadsTheExample) {
  const Case c = read_case(kExample);
  EXPECT_EQ(c.source, kExample);
  EXPECT_EQ(c.title, "175/70R13, inflation 0.2 MPa");
  const TyreDescription& t = c.tyre;
  EXPECT_EQ(t.name, "175/70R13");
  ASSERT_EQ(t.profile.size(), 35u);
  EXPECT_EQ(t.profile.front(), Eigen::Vector2d(0.0, 272.0));
  EXPECT_EQ(t.profile[24], Eigen::Vector2d(82.47, 226.81));
  EXPECT_EQ(t.profile.back(), Eigen::Vector2d(68.0, 185.0));

  ASSERT_EQ(t.zones.size(), 4u);
  EXPECT_EQ(t.zones[0].name, "crown");
  EXPECT_EQ(t.zones[3].name, "lower sidewall");
  EXPECT_EQ(t.zones[0].s_end, 60.0);
  EXPECT_EQ(t.zones[2].s_end, 130.0);
  // the last zone is snapped to the bead
  EXPECT_DOUBLE_EQ(t.zones[3].s_end, MeridianProfile(t.profile).length());
  EXPECT_NEAR(t.zones[3].s_end, 153.9, 0.1);

  const Zone& crown = t.zones[0];
  ASSERT_EQ(crown.inner.plies.size(), 2u);
  EXPECT_EQ(crown.inner.plies[0].name, "carcass");
  EXPECT_EQ(crown.inner.plies[0].cord_modulus, 3500.0);
  EXPECT_EQ(crown.inner.plies[0].angle_deg, 90.0);
  EXPECT_EQ(crown.inner.plies[0].rubber_poisson, 0.49);
  EXPECT_EQ(crown.inner.rule, CordRubberRule::halpin_tsai);
  ASSERT_EQ(crown.outer.plies.size(), 2u);
  EXPECT_EQ(crown.outer.plies[0].angle_deg, 22.0);
  EXPECT_EQ(crown.outer.plies[1].angle_deg, -22.0);
  EXPECT_EQ(crown.outer.plies[1].cord_area, 0.196);
  EXPECT_FALSE(crown.outer.direct_stiffness.has_value());
  EXPECT_EQ(crown.core_shear_modulus, 2.0);
  EXPECT_EQ(crown.core_normal_modulus, 100.0);

  ASSERT_TRUE(t.zones[1].outer.direct_stiffness.has_value());
  EXPECT_TRUE(t.zones[1].outer.plies.empty());
  EXPECT_EQ(*t.zones[1].outer.direct_stiffness, isotropic_membrane(4.0, 0.49, 8.0));
  EXPECT_EQ(t.zones[1].core_shear_modulus, 1.5);
  EXPECT_EQ(*t.zones[3].outer.direct_stiffness, isotropic_membrane(8.0, 0.49, 4.0));
  EXPECT_EQ(t.zones[3].core_shear_modulus, 2.0);

  EXPECT_DOUBLE_EQ(t.interlayer_thickness.at(0.0), 3.0);
  EXPECT_DOUBLE_EQ(t.interlayer_thickness.at(62.5), 4.5);
  EXPECT_DOUBLE_EQ(t.interlayer_thickness.at(153.9), 8.0);
  EXPECT_DOUBLE_EQ(t.tread_height.at(62.5), 9.0);
  EXPECT_EQ(t.tread_end_s, 78.0);
  EXPECT_EQ(t.tread_stiffness, 1.0);
  EXPECT_EQ(t.tread_shear_modulus, 0.55);

  EXPECT_EQ(c.mesh.circumferential_elements, 120);
  EXPECT_EQ(c.mesh.meridional_elements, 46);
  EXPECT_TRUE(c.mesh.half_model);
  EXPECT_EQ(c.mesh.circumferential_refinement, 4.0);
  EXPECT_TRUE(c.inflation.enabled);
  EXPECT_EQ(c.inflation.pressure, 0.2);
  EXPECT_FALSE(c.inflation.linear);
  EXPECT_NO_THROW(validate_case(c));
}

TEST(CaseReader, SyntaxErrorsGiveLineAndColumn) {
  const std::string text = edited("pressure = 0.2", "pressure = = 0.2");
  const std::string e = error_of(text);
  const std::string w = where(text, "pressure = =");                            // "case.toml:LINE:COL: "
  EXPECT_EQ(e.rfind(w.substr(0, w.rfind(':', w.size() - 3) + 1), 0), 0u) << e;  // same file and line
  EXPECT_CONTAINS(e, "TOML syntax error");
}

TEST(CaseReader, ValueErrorsNameFileLineFieldAndExpectation) {
  const std::string text = edited("value = [3.0,  3.0,  6.0,  5.0,", "value = [3.0,  3.0,  6.0,  -1,");
  EXPECT_EQ(error_of(text), where(text, "-1,") + "tyre.interlayer.thickness.value[3]: must be > 0 (got -1)");
}

TEST(CaseReader, UnknownKeysAreErrorsWithASuggestion) {
  const std::string text = edited("core_shear_modulus = 0.8", "core_shear_modolus = 0.8");
  const std::string e = error_of(text);
  EXPECT_CONTAINS(e, where(text, "core_shear_modolus") + "tyre.zones[2].core_shear_modolus: unknown key");
  EXPECT_CONTAINS(e, "did you mean 'core_shear_modulus'");
  EXPECT_CONTAINS(error_of(edited("[mesh]", "[mesh]\nelements = 3")), "mesh.elements: unknown key");
  EXPECT_CONTAINS(error_of(edited("title =", "titel =")), "titel: unknown key");
}

TEST(CaseReader, MissingFields) {
  EXPECT_CONTAINS(error_of(edited("core_shear_modulus = 0.8\n", "")),
                  "tyre.zones[2].core_shear_modulus: missing; expected a number (MPa)");
  EXPECT_CONTAINS(error_of(edited("cord_area = 0.33\n", "")), "tyre.plies.carcass.cord_area: missing");
  EXPECT_CONTAINS(error_of(edited("end_s = 78.0\n", "")), "tyre.tread.end_s: missing");
}

TEST(CaseReader, WrongTypes) {
  EXPECT_CONTAINS(error_of(edited("pressure = 0.2", "pressure = \"high\"")),
                  "inflation.pressure: must be a number (MPa) (got a string)");
  EXPECT_CONTAINS(error_of(edited("circumferential_elements = 120", "circumferential_elements = 120.5")),
                  "mesh.circumferential_elements: must be an integer (got a floating-point number)");
  EXPECT_CONTAINS(error_of(edited("half_model = true", "half_model = 1")),
                  "mesh.half_model: must be true or false");
  EXPECT_CONTAINS(error_of(edited("[82.47, 226.81]", "[82.47]")),
                  "tyre.profile.points[24]: must be a pair [x, r]");
  EXPECT_CONTAINS(error_of(edited("cord_rubber_rule = \"halpin_tsai\"", "cord_rubber_rule = \"gough\"")),
                  "tyre.cord_rubber_rule: must be \"halpin_tsai\" or \"gough_tangorra\" (got \"gough\")");
}

TEST(CaseReader, NonPositiveModuliAndThicknesses) {
  const std::string text = edited("thickness = 1.2\nrubber_modulus = 6.0\n\n[tyre.plies.belt2]",
                                  "thickness = 0\nrubber_modulus = 6.0\n\n[tyre.plies.belt2]");
  EXPECT_EQ(error_of(text), where(text, "0\nrubber_modulus = 6.0\n\n[tyre.plies.belt2]") +
                                "tyre.plies.belt1.thickness: must be > 0 (got 0)");
  EXPECT_CONTAINS(error_of(edited("core_shear_modulus = 0.8", "core_shear_modulus = -0.8")),
                  "tyre.zones[2].core_shear_modulus: must be > 0 (got -0.8)");
  EXPECT_CONTAINS(error_of(edited("E = 3.0", "E = 0.0")),
                  "tyre.zones[2].outer.rubber.E: must be > 0 (got 0)");
  EXPECT_CONTAINS(error_of(edited("stiffness = 1.0", "stiffness = -1.0")),
                  "tyre.tread.stiffness: must be > 0");
  EXPECT_CONTAINS(
      error_of(edited("ends_per_mm = 1.0", "ends_per_mm = 4.0")),
      "tyre.plies.carcass: cord volume fraction cord_area × ends_per_mm / thickness must be < 1 (got 1.32)");
}

TEST(CaseReader, ProfileMustStartAtTheEquatorAndAdvance) {
  EXPECT_CONTAINS(error_of(edited("[ 0.00, 272.00]", "[ 1.00, 272.00]")),
                  "tyre.profile.points[0]: the profile must start on the equator, x = 0 (got x = 1)");
  EXPECT_CONTAINS(error_of(edited("[14.69, 271.64], [19.58, 271.36]", "[19.58, 271.36], [14.69, 271.64]")),
                  "tyre.profile.points[4]: the profile turns back at points[3]");
  EXPECT_CONTAINS(error_of(edited("[14.69, 271.64], [19.58, 271.36]", "[14.69, 271.64], [14.69, 271.64]")),
                  "tyre.profile.points[4]: same point as points[3]: arc length must increase");
  EXPECT_CONTAINS(error_of(edited("[ 4.90, 271.96]", "[ -4.90, 271.96]")),
                  "tyre.profile.points[1]: x must be ≥ 0");
}

TEST(CaseReader, ZonesMustAdvanceAndReachTheBead) {
  EXPECT_CONTAINS(error_of(edited("s_end = 60.0", "s_end = 90.0")),
                  "tyre.zones[1].s_end: must be greater than the previous zone's s_end = 90 (got 82)");
  const std::string short_zone = error_of(edited("s_end = 153.9", "s_end = 150.0"));
  EXPECT_CONTAINS(short_zone, "tyre.zones[3].s_end: the last zone must end at the bead");
  EXPECT_CONTAINS(short_zone, "got 150");
  const Case near = parse_case(edited("s_end = 153.9", "s_end = 153.2"), "case.toml");
  EXPECT_DOUBLE_EQ(near.tyre.zones[3].s_end, MeridianProfile(near.tyre.profile).length());
}

TEST(CaseReader, TablesMustIncrease) {
  const std::string text = edited("s = [0.0, 55.0, 70.0, 78.0]", "s = [0.0, 55.0, 50.0, 78.0]");
  EXPECT_EQ(error_of(text),
            where(text, "50.0, 78.0]") + "tyre.tread.height.s[2]: must be greater than s[1] = 55 (got 50)");
  EXPECT_CONTAINS(error_of(edited("value = [10.0, 10.0, 8.0, 8.0]", "value = [10.0, 10.0, 8.0]")),
                  "tyre.tread.height.value: must have as many entries as s (4; got 3)");
}

TEST(CaseReader, MeshAndInflationLimits) {
  EXPECT_CONTAINS(error_of(edited("meridional_elements = 46", "meridional_elements = 0")),
                  "mesh.meridional_elements: must be ≥ the number of zones, 4 (got 0)");
  EXPECT_CONTAINS(error_of(edited("circumferential_elements = 120", "circumferential_elements = -5")),
                  "mesh.circumferential_elements: must be ≥ 3 (got -5)");
  EXPECT_CONTAINS(error_of(edited("circumferential_refinement = 4.0", "circumferential_refinement = 0.5")),
                  "mesh.circumferential_refinement: must be ≥ 1 (got 0.5)");
  EXPECT_CONTAINS(error_of(edited("pressure = 0.2", "pressure = -0.2")),
                  "inflation.pressure: must be > 0 (got -0.2)");
}

TEST(CaseReader, PlyAnglesAndNames) {
  EXPECT_CONTAINS(error_of(edited("angle = 90.0", "angle = 95.0")),
                  "tyre.plies.carcass.angle: must be in [-90, 90] (got 95)");
  const std::string text =
      edited(kBeltFace, "outer = { plies = [\"belt1\", \"belt3\"] }");
  EXPECT_EQ(error_of(text), where(text, "\"belt3\"") +
                                "tyre.zones[0].outer.plies[1]: unknown ply \"belt3\" (defined in "
                                "[tyre.plies]: belt1, belt2, carcass)");
  EXPECT_CONTAINS(error_of(edited(kBeltFace, "outer = { }")),
                  "tyre.zones[0].outer: a face needs at least one of plies, rubber or stiffness");
}

TEST(CaseReader, OtherFaceForms) {
  // direct orthotropic stiffness, an inline ply, a rule override, rubber layers as an array, constants
  std::string text = edited(kBeltFace,
                            "outer = { stiffness = [[1000, 6000, 0], [6000, 37000, 0], [0, 0, 6000]] }");
  auto replace_first = [&text](std::string_view from, std::string_view to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace_first("inner = { plies = [\"carcass\", \"carcass\"] }",
                "inner = { plies = [\"carcass\", { cord_modulus = 3500, cord_area = 0.33, ends_per_mm = 1, "
                "angle = 90, thickness = 1, rubber_modulus = 4 }], rule = \"gough_tangorra\" }");
  replace_first("rubber = { E = 4.0, nu = 0.49, thickness = 8.0 }",
                "rubber = [{ E = 4.0, thickness = 4.0 }, { E = 4.0, thickness = 4.0 }]");
  const Case c = parse_case(text, "case.toml");
  EXPECT_EQ((*c.tyre.zones[0].outer.direct_stiffness)(1, 1), 37000.0);
  EXPECT_EQ(c.tyre.zones[0].inner.rule, CordRubberRule::gough_tangorra);
  EXPECT_EQ(c.tyre.zones[0].inner.plies[1].cord_area, 0.33);
  EXPECT_EQ(c.tyre.zones[1].inner.rule, CordRubberRule::halpin_tsai);
  EXPECT_LT((*c.tyre.zones[1].outer.direct_stiffness - isotropic_membrane(4.0, 0.49, 8.0)).norm(), 1e-12);

  EXPECT_CONTAINS(
      error_of(edited(kBeltFace,
                      "outer = { stiffness = [[1000, 6000, 0], [5000, 37000, 0], [0, 0, 6000]] }")),
      "tyre.zones[0].outer.stiffness: must be symmetric");
  EXPECT_CONTAINS(
      error_of(edited(kBeltFace,
                      "outer = { stiffness = [[1000, 9000, 0], [9000, 37000, 0], [0, 0, 6000]] }")),
      "tyre.zones[0].outer.stiffness: must be positive definite");

  const Case constant = parse_case(
      edited("[tyre.interlayer.thickness]\ns     = [0.0, 55.0, 70.0, 82.0, 95.0, 125.0, 140.0, 153.9]\n"
             "value = [3.0,  3.0,  6.0,  5.0,  3.5,   3.5,   8.0,   8.0]",
             "[tyre.interlayer]\nthickness = 3.5"),
      "case.toml");
  EXPECT_EQ(constant.tyre.interlayer_thickness.at(100.0), 3.5);
}

TEST(CaseReader, DefaultsWhenSectionsAreLeftOut) {
  std::string text = example_text();
  text.erase(text.find("# Finite-element mesh"));
  const Case c = parse_case(text, "case.toml");
  EXPECT_EQ(c.mesh.circumferential_elements, MeshSettings{}.circumferential_elements);
  EXPECT_EQ(c.inflation.pressure, InflationSettings{}.pressure);
}

TEST(CaseReader, MissingFileAndProgrammaticValidation) {
  try {
    read_case("no/such/case.toml");
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_CONTAINS(std::string(e.what()), "no/such/case.toml: cannot open");
  }
  Case c = read_case(kExample);
  c.tyre.zones[2].core_shear_modulus = -1.0;
  try {
    validate_case(c);
    FAIL() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()),
              kExample.string() + ": tyre.zones[2].core_shear_modulus: must be > 0 (got -1)");
  }
}

}  // namespace
}  // namespace tirefem

namespace tirefem {
namespace {

using namespace case_test;

TEST(CaseReader, ReadsAFacesBendingStiffnessIntoItsZonesSections) {
  const Case c = parse_case(edited("outer = { rubber = { E = 3.0, nu = 0.49, thickness = 3.0 } }",
                                   "outer = { rubber = { E = 3.0, nu = 0.49, thickness = 3.0 }, "
                                   "bending_stiffness = [50.0, 60.0] }"),
                            "case.toml");
  EXPECT_EQ(c.tyre.zones[2].outer.bending_stiffness, Eigen::Vector2d(50.0, 60.0));
  EXPECT_EQ(c.tyre.zones[2].inner.bending_stiffness, Eigen::Vector2d::Zero());
  MeshSettings coarse = c.mesh;
  coarse.circumferential_elements = 24;
  coarse.meridional_elements = 12;
  const TyreMesh tm = build_tyre_mesh(c.tyre, coarse);
  int bent = 0;
  for (int e = 0; e < tm.mesh.element_count(); ++e) {
    bent += tm.sections[e].outer_face_bending == Eigen::Vector2d(50.0, 60.0);
    const Zone& zone = c.tyre.zones[tm.element_zone[e]];
    EXPECT_EQ(tm.sections[e].outer_face_bending, zone.outer.bending_stiffness) << e;
    EXPECT_EQ(tm.sections[e].inner_face_bending, zone.inner.bending_stiffness) << e;
  }
  EXPECT_GT(bent, 0);
}

}  // namespace
}  // namespace tirefem

namespace tirefem {
namespace {

using namespace case_test;

TEST(CaseReader, ReadsTheRimFlangeIntoTheTyreAndItsMesh) {
  EXPECT_FALSE(read_case(kExample).tyre.rim_flange.has_value()) << "the main example leaves the flange out";
  const Case c = parse_case(edited("[tyre.tread]\n", "[tyre.rim_flange]\nradius = 9.5\nstiffness = 20.0\n\n[tyre.tread]\n"),
                            "case.toml");
  ASSERT_TRUE(c.tyre.rim_flange.has_value());
  EXPECT_EQ(c.tyre.rim_flange->radius, 9.5);
  EXPECT_EQ(c.tyre.rim_flange->stiffness, 20.0);
  EXPECT_NO_THROW(validate_case(c));
  MeshSettings coarse = c.mesh;
  coarse.circumferential_elements = 24;
  coarse.meridional_elements = 12;
  const TyreMesh tm = build_tyre_mesh(c.tyre, coarse);
  ASSERT_TRUE(tm.rim_flange.has_value());
  EXPECT_EQ(tm.rim_flange->stiffness, 20.0);
}

}  // namespace
}  // namespace tirefem
