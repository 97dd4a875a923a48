// The case reader's studies: [contact], [[load_curve]] and [[footprint]] with their supports. The example
// case reads back with the paper's studies, omitted keys take the structs' defaults, and every kind of
// input error names the file, the line and column where known, the full field path and what was expected.
#include "tirefem/case/case_reader.hpp"

#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"

namespace tirefem {
namespace {

using namespace case_test;

const std::string kDrum = "name = \"drum\"\nsupport = { kind = \"drum\", diameter = 1830.0 }";

using Kind = SupportDescription::Kind;

TEST(CaseReaderStudies, ReadsTheExampleStudies) {
  const Case c = read_case(kExample);
  EXPECT_EQ(c.contact.quadrature, 4);
  EXPECT_EQ(c.contact.iteration, ContactSettings::Iteration::single_loop);
  EXPECT_EQ(c.contact.max_contact_iterations, 30);
  EXPECT_EQ(c.contact.region_tolerance, 0);
  EXPECT_EQ(c.contact.max_newton_iterations, 25);
  EXPECT_EQ(c.contact.max_state_iterations, 250);  // the default
  EXPECT_EQ(c.contact.residual_tolerance, 1e-8);

  ASSERT_EQ(c.load_curves.size(), 3u);
  const LoadCurveStudy& plane = c.load_curves[0];
  EXPECT_EQ(plane.name, "plane");
  EXPECT_EQ(plane.support.kind, Kind::plane);
  EXPECT_FALSE(plane.linear);
  EXPECT_EQ(plane.max_deflection, 40.0);
  EXPECT_EQ(plane.points, 20);
  const LoadCurveStudy& drum = c.load_curves[1];
  EXPECT_EQ(drum.name, "drum");
  EXPECT_EQ(drum.support.kind, Kind::drum);
  EXPECT_EQ(drum.support.drum_diameter, 1830.0);
  EXPECT_FALSE(drum.linear);
  EXPECT_EQ(drum.max_deflection, 40.0);
  EXPECT_EQ(drum.points, 20);
  const LoadCurveStudy& linear = c.load_curves[2];
  EXPECT_EQ(linear.name, "plane_linear");
  EXPECT_EQ(linear.support.kind, Kind::plane);
  EXPECT_TRUE(linear.linear);
  EXPECT_EQ(linear.max_deflection, 40.0);
  EXPECT_EQ(linear.points, 20);

  ASSERT_EQ(c.footprints.size(), 1u);
  const FootprintStudy& f = c.footprints[0];
  EXPECT_EQ(f.name, "footprint_3700N");
  EXPECT_EQ(f.support.kind, Kind::plane);
  EXPECT_FALSE(f.linear);
  EXPECT_EQ(f.target_load, 3700.0);
  EXPECT_EQ(f.load_tolerance, 1e-3);
  EXPECT_NO_THROW(validate_case(c));
}

TEST(CaseReaderStudies, DefaultsWhenKeysAreOmitted) {
  const Case none = parse_case(tyre_with(""), "case.toml");
  EXPECT_TRUE(none.load_curves.empty());
  EXPECT_TRUE(none.footprints.empty());
  EXPECT_EQ(none.contact.quadrature, ContactSettings{}.quadrature);

  const Case c = parse_case(tyre_with("[contact]\n"
                                      "[[load_curve]]\nname = \"a\"\nsupport = { kind = \"plane\" }\n"
                                      "[[footprint]]\nname = \"b\"\nsupport = { kind = \"plane\" }\n"),
                            "case.toml");
  const ContactSettings d;
  EXPECT_EQ(c.contact.quadrature, d.quadrature);
  EXPECT_EQ(c.contact.iteration, d.iteration);
  EXPECT_EQ(c.contact.max_contact_iterations, d.max_contact_iterations);
  EXPECT_EQ(c.contact.region_tolerance, d.region_tolerance);
  EXPECT_EQ(c.contact.max_newton_iterations, d.max_newton_iterations);
  EXPECT_EQ(c.contact.residual_tolerance, d.residual_tolerance);
  ASSERT_EQ(c.load_curves.size(), 1u);
  EXPECT_EQ(c.load_curves[0].name, "a");
  EXPECT_EQ(c.load_curves[0].linear, LoadCurveStudy{}.linear);
  EXPECT_EQ(c.load_curves[0].max_deflection, LoadCurveStudy{}.max_deflection);
  EXPECT_EQ(c.load_curves[0].points, LoadCurveStudy{}.points);
  ASSERT_EQ(c.footprints.size(), 1u);
  EXPECT_EQ(c.footprints[0].name, "b");
  EXPECT_EQ(c.footprints[0].linear, FootprintStudy{}.linear);
  EXPECT_EQ(c.footprints[0].target_load, FootprintStudy{}.target_load);
  EXPECT_EQ(c.footprints[0].load_tolerance, FootprintStudy{}.load_tolerance);

  // the other values of the enum-like keys
  const Case other = parse_case(
      tyre_with("[contact]\niteration = \"single_loop\"\nquadrature = 8\nregion_tolerance = 3\n"
                "equilibrium = \"stable\"\n"
                "[[footprint]]\nname = \"f-1\"\nsupport = { kind = \"plane\" }\ntheory = \"linear\"\n"
                "target_load = 5000\nload_tolerance = 0.05\n"),
      "case.toml");
  EXPECT_EQ(other.contact.iteration, ContactSettings::Iteration::single_loop);
  EXPECT_EQ(other.contact.quadrature, 8);
  EXPECT_EQ(other.contact.region_tolerance, 3);
  EXPECT_EQ(other.contact.equilibrium, ContactSettings::Equilibrium::stable);
  EXPECT_TRUE(other.footprints[0].linear);
  EXPECT_EQ(other.footprints[0].target_load, 5000.0);
  EXPECT_EQ(other.footprints[0].load_tolerance, 0.05);
}

TEST(CaseReaderStudies, SupportKinds) {
  // inline tables
  const Case c =
      parse_case(tyre_with("[[load_curve]]\nname = \"p\"\nsupport = { kind = \"plane\" }\n"
                           "[[load_curve]]\nname = \"d\"\nsupport = { kind = \"drum\", diameter = 2000 }\n"
                           "[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = [\n"
                           "  { coefficient = 1e-4, x_power = 0, y_power = 2 },\n"
                           "  { coefficient = -2e-5, x_power = 2 },\n"
                           "  { coefficient = 0.0, x_power = 0, y_power = 0 } ] }\n"),
                 "case.toml");
  ASSERT_EQ(c.load_curves.size(), 3u);
  EXPECT_EQ(c.load_curves[0].support.kind, Kind::plane);
  EXPECT_EQ(c.load_curves[1].support.kind, Kind::drum);
  EXPECT_EQ(c.load_curves[1].support.drum_diameter, 2000.0);
  const SupportDescription& s = c.load_curves[2].support;
  EXPECT_EQ(s.kind, Kind::surface);
  ASSERT_EQ(s.terms.size(), 3u);
  EXPECT_EQ(s.terms[0].coefficient, 1e-4);
  EXPECT_EQ(s.terms[0].x_power, 0);
  EXPECT_EQ(s.terms[0].y_power, 2);
  EXPECT_EQ(s.terms[1].coefficient, -2e-5);
  EXPECT_EQ(s.terms[1].x_power, 2);
  EXPECT_EQ(s.terms[1].y_power, 0);  // omitted power: 0
  EXPECT_EQ(s.terms[2].coefficient, 0.0);

  // sub-tables, and an array of tables for the terms
  const Case sub =
      parse_case(tyre_with("[[footprint]]\nname = \"d\"\n[footprint.support]\nkind = \"drum\"\n"
                           "diameter = 1500.0\n"
                           "[[footprint]]\nname = \"s\"\n[footprint.support]\nkind = \"surface\"\n"
                           "[[footprint.support.terms]]\ncoefficient = 3e-4\ny_power = 2\n"
                           "[[footprint.support.terms]]\ncoefficient = 1e-6\nx_power = 1\n"
                           "y_power = 3\n"),
                 "case.toml");
  ASSERT_EQ(sub.footprints.size(), 2u);
  EXPECT_EQ(sub.footprints[0].support.kind, Kind::drum);
  EXPECT_EQ(sub.footprints[0].support.drum_diameter, 1500.0);
  ASSERT_EQ(sub.footprints[1].support.terms.size(), 2u);
  EXPECT_EQ(sub.footprints[1].support.terms[0].y_power, 2);
  EXPECT_EQ(sub.footprints[1].support.terms[1].coefficient, 1e-6);
  EXPECT_EQ(sub.footprints[1].support.terms[1].x_power, 1);
  EXPECT_EQ(sub.footprints[1].support.terms[1].y_power, 3);
}

TEST(CaseReaderStudies, UnknownKeysInSupportsAndStudies) {
  // a typo
  std::string text = edited(kDrum, "name = \"drum\"\nsupport = { kind = \"drum\", diamter = 1830.0 }");
  EXPECT_EQ(error_of(text), where(text, "diamter") +
                                "load_curve[1].support.diamter: unknown key; expected one of: kind, "
                                "diameter (did you mean 'diameter'?)");
  // a key of another kind
  text = edited(kDrum, "name = \"drum\"\nsupport = { kind = \"plane\", diameter = 1830.0 }");
  EXPECT_EQ(error_of(text), where(text, "diameter = 1830") +
                                "load_curve[1].support.diameter: not allowed for kind \"plane\" (diameter "
                                "belongs to kind \"drum\"; a plane support takes no other keys)");
  text = edited(kDrum, "name = \"drum\"\nsupport = { kind = \"drum\", diameter = 1830.0, terms = [] }");
  EXPECT_EQ(error_of(text), where(text, "terms = []") +
                                "load_curve[1].support.terms: not allowed for kind \"drum\" (terms belongs "
                                "to kind \"surface\"; a drum support takes diameter)");
  text = edited(kDrum, "name = \"drum\"\nsupport = { kidn = \"drum\", diameter = 1830.0 }");
  EXPECT_EQ(error_of(text), where(text, "kidn") +
                                "load_curve[1].support.kidn: unknown key; expected one of: kind, diameter, "
                                "terms (did you mean 'kind'?)");
  // in a term, a study, [contact] and the root
  text = tyre_with(
      "[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = [{ coefficient = 1, xpower = 2 "
      "}] }\n");
  EXPECT_EQ(error_of(text), where(text, "xpower") +
                                "load_curve[0].support.terms[0].xpower: unknown key; expected one of: "
                                "coefficient, x_power, y_power (did you mean 'x_power'?)");
  text = edited("max_deflection = 40.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"",
                "max_deflexion = 40.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"");
  EXPECT_EQ(error_of(text), where(text, "max_deflexion") +
                                "load_curve[0].max_deflexion: unknown key; expected one of: name, support, "
                                "theory, max_deflection, points, deflection_from (did you mean 'max_deflection'?)");
  EXPECT_CONTAINS(error_of(edited("target_load = 3700.0", "target_load = 3700.0\npoints = 3")),
                  "footprint[0].points: unknown key; expected one of: name, support, theory, target_load, "
                  "load_tolerance");
  EXPECT_CONTAINS(error_of(edited("quadrature = 4", "quadratur = 4")),
                  "contact.quadratur: unknown key; expected one of: quadrature, iteration");
  EXPECT_CONTAINS(error_of(edited("quadrature = 4", "quadratur = 4")), "(did you mean 'quadrature'?)");
  EXPECT_CONTAINS(
      error_of(tyre_with("[[load_curves]]\nname = \"a\"\n")),
      "load_curves: unknown key; expected one of: title, tyre, mesh, inflation, contact, load_curve, "
      "footprint, rolling, tyre_test (did you mean 'load_curve'?)");
}

TEST(CaseReaderStudies, EnumLikeStringsListTheAcceptedValues) {
  std::string text = edited(kDrum, "name = \"drum\"\nsupport = { kind = \"cylinder\", diameter = 1830.0 }");
  EXPECT_EQ(error_of(text), where(text, "\"cylinder\"") +
                                "load_curve[1].support.kind: must be \"plane\", \"drum\" or \"surface\" (got "
                                "\"cylinder\")");
  text = edited("iteration = \"single_loop\"", "iteration = \"three_level\"");
  EXPECT_EQ(error_of(text), where(text, "\"three_level\"") +
                                "contact.iteration: must be \"two_level\" or \"single_loop\" (got "
                                "\"three_level\")");
  text = edited("equilibrium = \"stable\"", "equilibrium = \"lowest\"");
  EXPECT_EQ(error_of(text), where(text, "\"lowest\"") +
                                "contact.equilibrium: must be \"nearest\" or \"stable\" (got \"lowest\")");
  text = edited("theory = \"linear\"", "theory = \"small\"");
  EXPECT_EQ(error_of(text), where(text, "\"small\"") +
                                "load_curve[2].theory: must be \"nonlinear\" or \"linear\" (got \"small\")");
}

TEST(CaseReaderStudies, MissingAndWronglyTypedFields) {
  std::string text = edited(kDrum, "name = \"drum\"\nsupport = { kind = \"drum\" }");
  EXPECT_EQ(error_of(text), where(text, "{ kind = \"drum\" }") +
                                "load_curve[1].support.diameter: missing; expected a number (mm, the drum's "
                                "outer diameter)");
  EXPECT_CONTAINS(error_of(edited(kDrum, "name = \"drum\"\nsupport = { diameter = 1830.0 }")),
                  "load_curve[1].support.kind: missing; expected \"plane\", \"drum\" or \"surface\"");
  EXPECT_CONTAINS(error_of(edited(kDrum, "support = { kind = \"drum\", diameter = 1830.0 }")),
                  "load_curve[1].name: missing; expected a string");
  EXPECT_CONTAINS(error_of(edited(kDrum, "name = \"drum\"")),
                  "load_curve[1].support: missing; expected a table");
  EXPECT_CONTAINS(error_of(tyre_with("[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\" }\n")),
                  "load_curve[0].support.terms: missing; expected an array of terms");
  EXPECT_CONTAINS(
      error_of(tyre_with(
          "[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = [{ x_power = 2 }] }\n")),
      "load_curve[0].support.terms[0].coefficient: missing; expected a number");

  text = edited(kDrum, "name = \"drum\"\nsupport = \"drum\"");
  EXPECT_EQ(error_of(text), where(text, "\"drum\"   #") +
                                "load_curve[1].support: must be a table { kind = \"plane\", \"drum\" or "
                                "\"surface\", ... } (got a string)");
  EXPECT_CONTAINS(
      error_of(tyre_with("[[load_curve]]\nname = \"p\"\nsupport = { kind = \"plane\" }\npoints = 2.5\n")),
      "load_curve[0].points: must be an integer (got a floating-point number)");
  EXPECT_CONTAINS(error_of(tyre_with("[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = "
                                     "[{ coefficient = 1, y_power = 2.0 }] }\n")),
                  "load_curve[0].support.terms[0].y_power: must be an integer (got a floating-point number)");
  EXPECT_CONTAINS(error_of(tyre_with("[[footprint]]\nname = 7\nsupport = { kind = \"plane\" }\n")),
                  "footprint[0].name: must be a string (got an integer)");
  EXPECT_CONTAINS(error_of(tyre_with("[load_curve]\nname = \"a\"\nsupport = { kind = \"plane\" }\n")),
                  "load_curve: must be an array of tables [[load_curve]] (got a table)");
  EXPECT_CONTAINS(error_of(edited("target_load = 3700.0", "target_load = \"3700 N\"")),
                  "footprint[0].target_load: must be a number (N) (got a string)");
  EXPECT_CONTAINS(error_of(edited("iteration = \"single_loop\"", "iteration = 2")),
                  "contact.iteration: must be a string (got an integer)");
}

TEST(CaseReaderStudies, ValueRanges) {
  std::string text = edited("max_deflection = 40.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"",
                            "max_deflection = -5.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"");
  EXPECT_EQ(error_of(text), where(text, "-5.0") + "load_curve[0].max_deflection: must be > 0 (got -5)");
  text = edited("points = 20\n\n[[load_curve]]\nname = \"drum\"",
                "points = 0\n\n[[load_curve]]\nname = \"drum\"");
  EXPECT_EQ(error_of(text), where(text, "0\n\n[[load_curve]]\nname = \"drum\"") +
                                "load_curve[0].points: must be ≥ 1 (got 0)");
  text = edited(kDrum, "name = \"drum\"\nsupport = { kind = \"drum\", diameter = 0.0 }");
  EXPECT_EQ(error_of(text), where(text, "0.0 }") + "load_curve[1].support.diameter: must be > 0 (got 0)");
  EXPECT_CONTAINS(error_of(edited("target_load = 3700.0", "target_load = -1")),
                  "footprint[0].target_load: must be > 0 (got -1)");
  EXPECT_CONTAINS(error_of(edited("load_tolerance = 1e-3", "load_tolerance = 0.1")),
                  "footprint[0].load_tolerance: must be > 0 and < 0.1 (got 0.1)");
  EXPECT_CONTAINS(error_of(edited("load_tolerance = 1e-3", "load_tolerance = 0")),
                  "footprint[0].load_tolerance: must be > 0 and < 0.1 (got 0)");

  text = edited("quadrature = 4", "quadrature = 9");
  EXPECT_EQ(error_of(text), where(text, "9\niteration") + "contact.quadrature: must be in [1, 8] (got 9)");
  EXPECT_CONTAINS(error_of(edited("quadrature = 4", "quadrature = 0")),
                  "contact.quadrature: must be in [1, 8] (got 0)");
  EXPECT_CONTAINS(error_of(edited("max_contact_iterations = 30", "max_contact_iterations = 0")),
                  "contact.max_contact_iterations: must be ≥ 1 (got 0)");
  EXPECT_CONTAINS(error_of(edited("region_tolerance = 0", "region_tolerance = -1")),
                  "contact.region_tolerance: must be ≥ 0 (got -1)");
  EXPECT_CONTAINS(error_of(tyre_with("[contact]\nmax_newton_iterations = 0\n")),
                  "contact.max_newton_iterations: must be ≥ 1 (got 0)");
  EXPECT_CONTAINS(error_of(tyre_with("[contact]\nresidual_tolerance = 0.0\n")),
                  "contact.residual_tolerance: must be > 0 (got 0)");
}

TEST(CaseReaderStudies, SurfaceTerms) {
  std::string text = tyre_with(
      "[[footprint]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = [\n"
      "  { coefficient = 1e-4, y_power = 2 },\n  { coefficient = 0.5, x_power = 0, y_power = 0 } ] }\n");
  EXPECT_EQ(error_of(text),
            where(text, "0.5, x_power") +
                "footprint[0].support.terms[1].coefficient: a constant term (x_power = y_power "
                "= 0) must be zero (got 0.5): the road must pass through the origin, where "
                "the undeformed tyre touches it");
  text = tyre_with(
      "[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = [\n"
      "  { coefficient = 1e-4, y_power = 2 },\n  { coefficient = 1e-4, y_power = 2 },\n"
      "  { coefficient = 1e-9, x_power = 9 } ] }\n");
  EXPECT_EQ(error_of(text),
            where(text, "9 }") + "load_curve[0].support.terms[2].x_power: must be in [0, 8] (got 9)");
  EXPECT_CONTAINS(error_of(tyre_with("[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = "
                                     "[{ coefficient = 1, y_power = -2 }] }\n")),
                  "load_curve[0].support.terms[0].y_power: must be in [0, 8] (got -2)");
  EXPECT_CONTAINS(error_of(tyre_with("[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = "
                                     "[{ coefficient = nan, y_power = 2 }] }\n")),
                  "load_curve[0].support.terms[0].coefficient: must be a finite number (got nan)");
  EXPECT_CONTAINS(
      error_of(tyre_with("[[load_curve]]\nname = \"s\"\nsupport = { kind = \"surface\", terms = [] }\n")),
      "load_curve[0].support.terms: a surface needs at least one term");
}

TEST(CaseReaderStudies, StudyNames) {
  std::string text = edited("name = \"footprint_3700N\"", "name = \"drum\"");
  EXPECT_EQ(error_of(text),
            where(text, "\"drum\"\nsupport = { kind = \"plane\" }\ntheory = \"nonlinear\"\ntarget") +
                "footprint[0].name: duplicate name \"drum\" (already used by load_curve[1].name); "
                "load curves, footprints and rolling studies need distinct names");
  text = edited("name = \"plane_linear\"", "name = \"plane\"");
  EXPECT_EQ(error_of(text), where(text, "\"plane\"\nsupport = { kind = \"plane\" }\ntheory = \"linear\"") +
                                "load_curve[2].name: duplicate name \"plane\" (already used by "
                                "load_curve[0].name); load curves, footprints and rolling studies need distinct names");
  text = edited("name = \"footprint_3700N\"", "name = \"footprint 3700 N\"");
  EXPECT_EQ(error_of(text),
            where(text, "\"footprint 3700 N\"") +
                "footprint[0].name: may contain only letters A-Z a-z, digits 0-9, '_' and '-' "
                "(got \"footprint 3700 N\")");
  EXPECT_CONTAINS(error_of(edited("name = \"plane_linear\"", "name = \"plane/linear\"")),
                  "load_curve[2].name: may contain only letters");
  EXPECT_CONTAINS(error_of(edited("name = \"plane_linear\"", "name = \"Ebene_ä\"")),
                  "load_curve[2].name: may contain only letters");
  EXPECT_CONTAINS(error_of(edited("name = \"plane_linear\"", "name = \"\"")),
                  "load_curve[2].name: must not be empty");
}

TEST(CaseReaderStudies, ValidateCaseOnACaseBuiltInCode) {
  const Case good = read_case(kExample);
  const auto error = validation_error_of;
  const std::string file = kExample.string() + ": ";

  Case c = good;
  c.load_curves[1].support.drum_diameter = -1.0;
  EXPECT_EQ(error(c), file + "load_curve[1].support.diameter: must be > 0 (got -1)");
  c = good;
  c.load_curves[0].support.drum_diameter = -1.0;  // not a drum: the diameter is not used
  EXPECT_EQ(error(c), "(no error)");
  c = good;
  c.footprints[0].name = "plane_linear";
  EXPECT_EQ(error(c), file +
                          "footprint[0].name: duplicate name \"plane_linear\" (already used by "
                          "load_curve[2].name); load curves, footprints and rolling studies need distinct names");
  c = good;
  c.contact.quadrature = 12;
  EXPECT_EQ(error(c), file + "contact.quadrature: must be in [1, 8] (got 12)");
  c = good;
  c.load_curves[2].points = 0;
  EXPECT_EQ(error(c), file + "load_curve[2].points: must be ≥ 1 (got 0)");
  c = good;
  c.footprints[0].support.kind = Kind::surface;  // no terms
  EXPECT_EQ(error(c),
            file +
                "footprint[0].support.terms: a surface needs at least one term { coefficient, x_power, "
                "y_power }");
  c.footprints[0].support.terms = {{1e-4, 0, 2}, {2.0, 0, 0}};
  EXPECT_CONTAINS(error(c), file + "footprint[0].support.terms[1].coefficient: a constant term");
  c.footprints[0].support.terms = {{1e-4, 0, 2}};
  EXPECT_EQ(error(c), "(no error)");

  Case anonymous = good;
  anonymous.source.clear();
  anonymous.load_curves[0].max_deflection = 0.0;
  EXPECT_EQ(error(anonymous), "case: load_curve[0].max_deflection: must be > 0 (got 0)");
}

}  // namespace
}  // namespace tirefem
