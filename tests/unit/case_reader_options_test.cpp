// The case reader's modelling options of issue 10 item 5: where deflections are measured from
// (deflection_from), footprints at a given deflection, and the meridional grading of the mesh.
#include "tirefem/case/case_reader.hpp"
#include "tirefem/tyre/tyre_mesh.hpp"

#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"

namespace tirefem {
namespace {

using namespace case_test;

const std::string kFootprint = "[[footprint]]\nname = \"f\"\nsupport = { kind = \"plane\" }\n";
const std::string kLoadCurve = "[[load_curve]]\nname = \"c\"\nsupport = { kind = \"plane\" }\n";

TEST(CaseReaderOptions, DeflectionsAreFromTheUndeformedTyreByDefault) {
  const Case c = parse_case(tyre_with(kLoadCurve + kFootprint), "case.toml");
  EXPECT_EQ(c.load_curves[0].deflection_from, DeflectionOrigin::undeformed);
  EXPECT_EQ(c.footprints[0].deflection_from, DeflectionOrigin::undeformed);
  EXPECT_FALSE(c.footprints[0].deflection.has_value());
  EXPECT_EQ(c.footprints[0].target_load, 3700.0);
  EXPECT_EQ(c.mesh.meridional_grading, MeshSettings::MeridionalGrading::zones);
}

TEST(CaseReaderOptions, ReadsDeflectionFromAndAFootprintAtADeflection) {
  const Case c = parse_case(tyre_with(kLoadCurve + "deflection_from = \"first_touch\"\nmax_deflection = 30.0\n" +
                                      kFootprint + "deflection = 20.0\ndeflection_from = \"first_touch\"\n"),
                            "case.toml");
  EXPECT_EQ(c.load_curves[0].deflection_from, DeflectionOrigin::first_touch);
  EXPECT_EQ(c.load_curves[0].max_deflection, 30.0);
  EXPECT_EQ(c.footprints[0].deflection_from, DeflectionOrigin::first_touch);
  ASSERT_TRUE(c.footprints[0].deflection.has_value());
  EXPECT_EQ(*c.footprints[0].deflection, 20.0);
  const Case u = parse_case(tyre_with(kFootprint + "deflection = 0.0\ndeflection_from = \"undeformed\"\n"),
                            "case.toml");
  EXPECT_EQ(u.footprints[0].deflection_from, DeflectionOrigin::undeformed);
  EXPECT_EQ(*u.footprints[0].deflection, 0.0);
}

TEST(CaseReaderOptions, FootprintAtALoadOrAtADeflectionNotBoth) {
  std::string text = tyre_with(kFootprint + "target_load = 3000.0\ndeflection = 20.0\n");
  EXPECT_EQ(error_of(text), where(text, "20.0", text.find("deflection = 20.0")) +
                                "footprint[0].deflection: give either target_load (the footprint at a load) or "
                                "deflection (at a deflection), not both");
  text = tyre_with(kFootprint + "deflection = -1.0\n");
  EXPECT_EQ(error_of(text), where(text, "-1.0") + "footprint[0].deflection: must be ≥ 0 (got -1)");
  text = tyre_with(kFootprint + "deflection = 150.0\n");
  EXPECT_CONTAINS(error_of(text), where(text, "150.0") + "footprint[0].deflection: must be less than the tyre's "
                                                          "section height");
  EXPECT_CONTAINS(error_of(tyre_with(kFootprint + "deflection = \"20 mm\"\n")),
                  "footprint[0].deflection: must be a number (mm) (got a string)");
  EXPECT_CONTAINS(error_of(tyre_with(kFootprint + "deflection = nan\n")), "footprint[0].deflection: must be a finite number");
}

TEST(CaseReaderOptions, DeflectionFromNamesItsChoices) {
  EXPECT_CONTAINS(error_of(tyre_with(kLoadCurve + "deflection_from = \"inflated\"\n")),
                  "load_curve[0].deflection_from: must be \"undeformed\" or \"first_touch\" (got \"inflated\")");
  EXPECT_CONTAINS(error_of(tyre_with(kFootprint + "deflection_from = 1\n")), "footprint[0].deflection_from");
}

TEST(CaseReaderOptions, ReadsTheMeridionalGrading) {
  const Case c = parse_case(
      edited("circumferential_refinement = 4.0\n", "circumferential_refinement = 4.0\nmeridional_grading = "
                                                   "\"uniform_arc_length\"\n"),
      "case.toml");
  EXPECT_EQ(c.mesh.meridional_grading, MeshSettings::MeridionalGrading::uniform_arc_length);
  EXPECT_CONTAINS(error_of(edited("circumferential_refinement = 4.0\n",
                                  "circumferential_refinement = 4.0\nmeridional_grading = \"uniform\"\n")),
                  "mesh.meridional_grading: must be \"zones\" or \"uniform_arc_length\" (got \"uniform\")");
  // Graded by zones, every zone needs an element; uniformly, fewer elements than zones are allowed.
  EXPECT_CONTAINS(error_of(edited("meridional_elements = 46", "meridional_elements = 3")),
                  "mesh.meridional_elements: must be ≥ the number of zones, 4 (got 3)");
  EXPECT_EQ(error_of(edited("meridional_elements = 46", "meridional_elements = 3\nmeridional_grading = "
                                                        "\"uniform_arc_length\"")),
            "(no error)");
}

TEST(CaseReaderOptions, ReadsTheFaceStrains) {
  EXPECT_EQ(parse_case(tyre_with(kLoadCurve), "case.toml").mesh.faces, MeshSettings::Faces::compatible);
  const Case c = parse_case(edited("circumferential_refinement = 4.0\n",
                                   "circumferential_refinement = 4.0\nfaces = \"enhanced\"\n"),
                            "case.toml");
  EXPECT_EQ(c.mesh.faces, MeshSettings::Faces::enhanced);
  const TyreMesh tm = build_tyre_mesh(c.tyre, c.mesh);
  EXPECT_TRUE(tm.sections.front().enhanced_faces);
  EXPECT_CONTAINS(error_of(edited("circumferential_refinement = 4.0\n",
                                  "circumferential_refinement = 4.0\nfaces = \"eas\"\n")),
                  "mesh.faces: must be \"compatible\" or \"enhanced\" (got \"eas\")");
}

}  // namespace
}  // namespace tirefem
