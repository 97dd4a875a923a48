// The case reader's [[rolling]] studies: a full study reads back with its states and sweep, omitted keys
// take the structs' defaults (state names included), and every input error names the file, the line and
// column where known, the full field path and what was expected; validate_case runs the same checks.
#include "tirefem/case/case_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"

namespace tirefem {
namespace {

using case_test::error_of;
using case_test::example_text;
using case_test::kExample;
using case_test::rolling_with;
using case_test::state;
using case_test::tyre_with;


// "case.toml:LINE:COL: " of the first occurrence of `needle` in `text` from its first [[rolling]] on.
std::string where(const std::string& text, std::string_view needle) {
  return case_test::where(text, needle, text.find("[[rolling]]"));
}

using Kind = RollingStateSpec::Kind;

TEST(CaseReaderRolling, ReadsAFullStudy) {
  const Case c =
      parse_case(tyre_with("[[rolling]]\n"
                           "name = \"rolling\"\n"
                           "support = { kind = \"drum\", diameter = 2000.0 }\n"
                           "target_load = 4000.0\n"
                           "load_tolerance = 2e-3\n"
                           "friction = 0.9\n"
                           "reverse = true\n"
                           "states = [\n"
                           "  { state = \"free\" },\n"
                           "  { state = \"given_slip\", slip = 0.05, name = \"traction_5pc\" },\n"
                           "  { state = \"given_slip\", slip = -0.025 },\n"
                           "  { state = \"given_radius\", rolling_radius = 280.0 },\n"
                           "  { state = \"full_stick\", slip = 0.01 },\n"
                           "  { state = \"full_stick\", name = \"stick+0\" },\n"
                           "  { state = \"full_slip\", wheel = \"spinning\" },\n"
                           "  { state = \"full_slip\", wheel = \"locked\" },\n"
                           "  { state = \"full_slip\", name = \"spin.2\" },\n"
                           "]\n"
                           "sweep = { from = -0.2, to = 0.3, points = 11 }\n"
                           "[[rolling]]\n"
                           "name = \"sweep_only\"\n"
                           "support = { kind = \"surface\", terms = [{ coefficient = 1e-4, x_power = 2 },\n"
                           "                                        { coefficient = 0.0, y_power = 2 }] }\n"
                           "sweep = {}\n"),
                 "case.toml");
  ASSERT_EQ(c.rolling.size(), 2u);
  const RollingStudy& r = c.rolling[0];
  EXPECT_EQ(r.name, "rolling");
  EXPECT_EQ(r.support.kind, SupportDescription::Kind::drum);
  EXPECT_EQ(r.support.drum_diameter, 2000.0);
  EXPECT_EQ(r.target_load, 4000.0);
  EXPECT_EQ(r.load_tolerance, 2e-3);
  EXPECT_EQ(r.friction, 0.9);
  EXPECT_TRUE(r.reverse);
  ASSERT_EQ(r.states.size(), 9u);
  struct Expected {
    Kind kind;
    std::string name;
    double slip, rolling_radius;
    bool braking;
  };
  const Expected expected[] = {
      {Kind::free, "free", 0.0, 0.0, false},
      {Kind::given_slip, "traction_5pc", 0.05, 0.0, false},
      {Kind::given_slip, "slip_-0.025", -0.025, 0.0, false},
      {Kind::given_radius, "radius_280", 0.0, 280.0, false},
      {Kind::full_stick, "full_stick", 0.01, 0.0, false},
      {Kind::full_stick, "stick+0", 0.0, 0.0, false},
      {Kind::full_slip, "full_slip_spinning", 0.0, 0.0, false},
      {Kind::full_slip, "full_slip_locked", 0.0, 0.0, true},
      {Kind::full_slip, "spin.2", 0.0, 0.0, false},
  };
  for (std::size_t k = 0; k < r.states.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(r.states[k].kind, expected[k].kind);
    EXPECT_EQ(r.states[k].name, expected[k].name);
    EXPECT_EQ(r.states[k].slip, expected[k].slip);
    EXPECT_EQ(r.states[k].rolling_radius, expected[k].rolling_radius);
    EXPECT_EQ(r.states[k].braking, expected[k].braking);
  }
  ASSERT_TRUE(r.sweep.has_value());
  EXPECT_EQ(r.sweep->from, -0.2);
  EXPECT_EQ(r.sweep->to, 0.3);
  EXPECT_EQ(r.sweep->points, 11);

  // omitted keys: the structs' defaults
  const RollingStudy& d = c.rolling[1];
  const RollingStudy defaults;
  EXPECT_EQ(d.name, "sweep_only");
  EXPECT_EQ(d.support.kind, SupportDescription::Kind::surface);
  EXPECT_EQ(d.support.terms.size(), 2u);  // y_power with a zero coefficient: no y dependence
  EXPECT_EQ(d.target_load, defaults.target_load);
  EXPECT_EQ(d.load_tolerance, defaults.load_tolerance);
  EXPECT_EQ(d.friction, defaults.friction);
  EXPECT_EQ(d.reverse, defaults.reverse);
  EXPECT_TRUE(d.states.empty());
  ASSERT_TRUE(d.sweep.has_value());
  EXPECT_EQ(d.sweep->from, SlipSweep{}.from);
  EXPECT_EQ(d.sweep->to, SlipSweep{}.to);
  EXPECT_EQ(d.sweep->points, SlipSweep{}.points);
  EXPECT_NO_THROW(validate_case(c));

  // a sub-table and an array of tables, and no sweep
  const Case sub = parse_case(tyre_with("[[rolling]]\nname = \"r\"\n[rolling.support]\nkind = \"plane\"\n"
                                        "[[rolling.states]]\nstate = \"given_slip\"\nslip = 1e-5\n"),
                              "case.toml");
  ASSERT_EQ(sub.rolling.size(), 1u);
  ASSERT_EQ(sub.rolling[0].states.size(), 1u);
  EXPECT_EQ(sub.rolling[0].states[0].name, "slip_1e-05");
  EXPECT_FALSE(sub.rolling[0].sweep.has_value());
}

TEST(CaseReaderRolling, TheExampleHasThePapersRollingStudies) {
  const Case c = read_case(kExample);
  ASSERT_EQ(c.rolling.size(), 3u);
  const RollingStudy& plane = c.rolling[0];
  EXPECT_EQ(plane.support.kind, SupportDescription::Kind::plane);
  EXPECT_EQ(plane.friction, 0.7);
  EXPECT_EQ(plane.target_load, 3700.0);
  ASSERT_TRUE(plane.mesh.has_value());
  EXPECT_EQ(plane.mesh->circumferential_elements, 80);
  EXPECT_EQ(plane.mesh->meridional_elements, 46);
  EXPECT_EQ(plane.states.size(), 5u);
  ASSERT_TRUE(plane.sweep.has_value());
  EXPECT_EQ(plane.sweep->points, 15);
  EXPECT_EQ(c.rolling[1].support.kind, SupportDescription::Kind::drum);
  // and the cornering study (issue 11): full model, the example's states, an α sweep with Qz held, a grid
  const RollingStudy& curve = c.rolling[2];
  ASSERT_TRUE(curve.mesh.has_value());
  EXPECT_FALSE(curve.mesh->half_model);
  EXPECT_EQ(curve.states.size(), 9u);
  ASSERT_TRUE(curve.angle_sweep.has_value());
  EXPECT_TRUE(curve.angle_sweep->hold_load);
  EXPECT_EQ(curve.angle_sweep->to, 12.0);
  ASSERT_TRUE(curve.combined.has_value());
}

TEST(CaseReaderRolling, RootAcceptsRolling) {
  EXPECT_CONTAINS(error_of(tyre_with("[[rollin]]\nname = \"r\"\n")),
                  "rollin: unknown key; expected one of: title, tyre, mesh, inflation, contact, load_curve, "
                  "footprint, rolling, tyre_test (did you mean 'rolling'?)");
  EXPECT_CONTAINS(error_of(tyre_with("[rolling]\nname = \"r\"\n")),
                  "rolling: must be an array of tables [[rolling]] (got a table)");
}

TEST(CaseReaderRolling, UnknownKeysSayDidYouMean) {
  std::string text = rolling_with("frictoin = 0.5");
  EXPECT_EQ(error_of(text), where(text, "frictoin") +
                                "rolling[0].frictoin: unknown key; expected one of: name, support, "
                                "target_load, load_tolerance, friction, reverse, states, sweep, angle_sweep, combined, "
                                "tread_shear, mesh (did you mean 'friction'?)");
  EXPECT_CONTAINS(error_of(rolling_with("theory = \"linear\"")), "rolling[0].theory: unknown key");
  text = rolling_with("sweep = { from = 0.0, point = 3 }");
  EXPECT_EQ(error_of(text), where(text, "point =") +
                                "rolling[0].sweep.point: unknown key; expected one of: from, to, points, hold (did "
                                "you mean 'points'?)");
  text = state("{ state = \"given_slip\", slipp = 0.1 }");
  EXPECT_EQ(error_of(text), where(text, "slipp") +
                                "rolling[0].states[0].slipp: unknown key; expected one of: state, name, slip, "
                                "slip_angle, camber, hold (did you mean 'slip'?)");
  text = state("{ stat = \"free\" }");
  EXPECT_EQ(error_of(text), where(text, "stat =") +
                                "rolling[0].states[0].stat: unknown key; expected one of: state, name, slip, "
                                "rolling_radius, wheel (did you mean 'state'?)");
}

TEST(CaseReaderRolling, StateIsRequiredAndFromAList) {
  std::string text = state("{ name = \"x\" }");
  EXPECT_EQ(error_of(text), where(text, "{ name") +
                                "rolling[0].states[0].state: missing; expected \"free\", \"given_slip\", "
                                "\"given_radius\", \"full_stick\" or \"full_slip\"");
  text = state("{ state = \"rolling\" }");
  EXPECT_EQ(error_of(text), where(text, "\"rolling\"") +
                                "rolling[0].states[0].state: must be \"free\", \"given_slip\", "
                                "\"given_radius\", \"full_stick\" or \"full_slip\" (got \"rolling\")");
  EXPECT_CONTAINS(error_of(rolling_with("", "states = [\"free\"]")),
                  "rolling[0].states[0]: must be a table { state = \"free\", ... } (got a string)");
  EXPECT_CONTAINS(error_of(rolling_with("", "states = { state = \"free\" }")),
                  "rolling[0].states: must be an array of states");
}

TEST(CaseReaderRolling, KeysOfAnotherStateAreErrors) {
  std::string text = state("{ state = \"full_slip\", slip = 0.1 }");
  EXPECT_EQ(error_of(text), where(text, "slip = 0.1") +
                                "rolling[0].states[0].slip: not allowed in a \"full_slip\" state (it takes "
                                "state, name and wheel)");
  text = state("{ state = \"free\", wheel = \"locked\" }");
  EXPECT_EQ(error_of(text), where(text, "wheel") +
                                "rolling[0].states[0].wheel: not allowed in a \"free\" state (it takes state, "
                                "name, slip_angle, camber and hold)");
  EXPECT_CONTAINS(error_of(state("{ state = \"given_slip\", slip = 0.1, rolling_radius = 280.0 }")),
                  "rolling[0].states[0].rolling_radius: not allowed in a \"given_slip\" state (it takes "
                  "state, name, slip, slip_angle, camber and hold)");
  EXPECT_CONTAINS(error_of(state("{ state = \"given_radius\", rolling_radius = 280.0, slip = 0.1 }")),
                  "rolling[0].states[0].slip: not allowed in a \"given_radius\" state (it takes state, name, "
                  "rolling_radius, slip_angle, camber and hold)");
  EXPECT_CONTAINS(error_of(state("{ state = \"full_slip\", slip_angle = 2.0 }")),
                  "rolling[0].states[0].slip_angle: not allowed in a \"full_slip\" state (it takes state, name "
                  "and wheel)");
}

TEST(CaseReaderRolling, GivenSlipNeedsASlipInRange) {
  std::string text = state("{ state = \"given_slip\" }");
  EXPECT_EQ(error_of(text), where(text, "{ state = \"given_slip\" }") +
                                "rolling[0].states[0].slip: missing; expected a number (slip κ)");
  text = rolling_with("",
                      "states = [{ state = \"free\" }, { state = \"full_stick\" },\n"
                      "  { state = \"given_slip\", slip = -1.5 }]");
  EXPECT_EQ(error_of(text), where(text, "-1.5") + "rolling[0].states[2].slip: must be > -1 (got -1.5)");
  EXPECT_CONTAINS(error_of(state("{ state = \"given_slip\", slip = -1.0 }")),
                  "rolling[0].states[0].slip: must be > -1 (got -1)");
  EXPECT_CONTAINS(error_of(state("{ state = \"given_slip\", slip = 10.5 }")),
                  "rolling[0].states[0].slip: must be ≤ 10 (got 10.5)");
  EXPECT_CONTAINS(error_of(state("{ state = \"given_slip\", slip = nan }")),
                  "rolling[0].states[0].slip: must be a finite number (got nan)");
  EXPECT_CONTAINS(error_of(state("{ state = \"given_slip\", slip = \"5%\" }")),
                  "rolling[0].states[0].slip: must be a number (slip κ) (got a string)");
  EXPECT_EQ(error_of(state("{ state = \"given_slip\", slip = 10 }")), "(no error)");
}

TEST(CaseReaderRolling, FullStickSlipIsOptionalButInRange) {
  EXPECT_EQ(error_of(state("{ state = \"full_stick\" }")), "(no error)");
  std::string text = state("{ state = \"full_stick\", slip = -2.0 }");
  EXPECT_EQ(error_of(text), where(text, "-2.0") + "rolling[0].states[0].slip: must be > -1 (got -2)");
  EXPECT_CONTAINS(error_of(state("{ state = \"full_stick\", slip = 11 }")),
                  "rolling[0].states[0].slip: must be ≤ 10 (got 11)");
}

TEST(CaseReaderRolling, GivenRadiusNeedsAPositiveRadius) {
  EXPECT_CONTAINS(error_of(state("{ state = \"given_radius\" }")),
                  "rolling[0].states[0].rolling_radius: missing; expected a number (mm)");
  std::string text = state("{ state = \"given_radius\", rolling_radius = -280.0 }");
  EXPECT_EQ(error_of(text),
            where(text, "-280.0") + "rolling[0].states[0].rolling_radius: must be > 0 (got -280)");
  EXPECT_CONTAINS(error_of(state("{ state = \"given_radius\", rolling_radius = 0 }")),
                  "rolling[0].states[0].rolling_radius: must be > 0 (got 0)");
}

TEST(CaseReaderRolling, WheelIsSpinningOrLocked) {
  std::string text = state("{ state = \"full_slip\", wheel = \"braking\" }");
  EXPECT_EQ(error_of(text), where(text, "\"braking\"") +
                                "rolling[0].states[0].wheel: must be \"spinning\" or \"locked\" (got "
                                "\"braking\")");
  EXPECT_CONTAINS(error_of(state("{ state = \"full_slip\", wheel = true }")),
                  "rolling[0].states[0].wheel: must be a string (got a boolean)");
}

TEST(CaseReaderRolling, StateNames) {
  // two default names alike: the second one is named
  std::string text = rolling_with("",
                                  "states = [{ state = \"given_slip\", slip = 0.1 },\n"
                                  "  { state = \"given_slip\", slip = 0.10 }]");
  EXPECT_EQ(error_of(text), where(text, "{ state = \"given_slip\", slip = 0.10 }") +
                                "rolling[0].states[1].name: duplicate state name \"slip_0.1\" (already used "
                                "by rolling[0].states[0].name); the states of a study need distinct names");
  text = rolling_with("", "states = [{ state = \"free\" }, { state = \"full_stick\", name = \"free\" }]");
  EXPECT_EQ(error_of(text), where(text, "\"free\" }]") +
                                "rolling[0].states[1].name: duplicate state name \"free\" (already used by "
                                "rolling[0].states[0].name); the states of a study need distinct names");
  // the same state name in two studies is fine
  EXPECT_EQ(error_of(tyre_with("[[rolling]]\nname = \"a\"\nsupport = { kind = \"plane\" }\n"
                               "states = [{ state = \"free\" }]\n"
                               "[[rolling]]\nname = \"b\"\nsupport = { kind = \"plane\" }\n"
                               "states = [{ state = \"free\" }]\n")),
            "(no error)");
  text = state("{ state = \"free\", name = \"free rolling\" }");
  EXPECT_EQ(error_of(text), where(text, "\"free rolling\"") +
                                "rolling[0].states[0].name: may contain only letters A-Z a-z, digits 0-9, "
                                "'_', '.', '+' and '-' (got \"free rolling\")");
  EXPECT_CONTAINS(error_of(state("{ state = \"free\", name = \"a/b\" }")),
                  "rolling[0].states[0].name: may contain only letters");
  EXPECT_CONTAINS(error_of(state("{ state = \"free\", name = \"\" }")),
                  "rolling[0].states[0].name: must not be empty");
  EXPECT_CONTAINS(error_of(state("{ state = \"free\", name = 3 }")),
                  "rolling[0].states[0].name: must be a string (got an integer)");
}

TEST(CaseReaderRolling, NeedsStatesOrASweep) {
  std::string text = tyre_with("[[rolling]]\nname = \"r\"\nsupport = { kind = \"plane\" }\n");
  EXPECT_EQ(error_of(text),
            where(text, "[[rolling]]") +
                "rolling[0]: needs states or a sweep (states = [{ state = \"free\" }, ...] or "
                "sweep = { from, to, points })");
  EXPECT_CONTAINS(error_of(rolling_with("", "states = []")), "rolling[0]: needs states or a sweep");
  EXPECT_EQ(error_of(rolling_with("sweep = { points = 3 }", "states = []")), "(no error)");
}

TEST(CaseReaderRolling, SweepRanges) {
  std::string text = rolling_with("sweep = { from = -1.0 }");
  EXPECT_EQ(error_of(text), where(text, "-1.0") + "rolling[0].sweep.from: must be > -1 (got -1)");
  text = rolling_with("sweep = { to = 12.0 }");
  EXPECT_EQ(error_of(text), where(text, "12.0") + "rolling[0].sweep.to: must be ≤ 10 (got 12)");
  text = rolling_with("sweep = { from = 0.1, to = -0.1 }");
  EXPECT_EQ(error_of(text),
            where(text, "-0.1 }") + "rolling[0].sweep.to: must be greater than from = 0.1 (got -0.1)");
  EXPECT_CONTAINS(error_of(rolling_with("sweep = { from = 0.1, to = 0.1 }")),
                  "rolling[0].sweep.to: must be greater than from = 0.1 (got 0.1)");
  text = rolling_with("sweep = { points = 1 }");
  EXPECT_EQ(error_of(text), where(text, "1 }") + "rolling[0].sweep.points: must be in [2, 200] (got 1)");
  EXPECT_CONTAINS(error_of(rolling_with("sweep = { points = 201 }")),
                  "rolling[0].sweep.points: must be in [2, 200] (got 201)");
  EXPECT_CONTAINS(error_of(rolling_with("sweep = { points = 2.0 }")),
                  "rolling[0].sweep.points: must be an integer (got a floating-point number)");
  EXPECT_CONTAINS(error_of(rolling_with("sweep = [-0.1, 0.1]")),
                  "rolling[0].sweep: must be a table (got an array)");
  EXPECT_EQ(error_of(rolling_with("sweep = { from = -0.99, to = 10.0, points = 200 }")), "(no error)");
}

TEST(CaseReaderRolling, LoadFrictionAndReverse) {
  std::string text = rolling_with("target_load = -3700.0");
  EXPECT_EQ(error_of(text), where(text, "-3700.0") + "rolling[0].target_load: must be > 0 (got -3700)");
  EXPECT_CONTAINS(error_of(rolling_with("target_load = \"3700 N\"")),
                  "rolling[0].target_load: must be a number (N) (got a string)");
  EXPECT_CONTAINS(error_of(rolling_with("load_tolerance = 0.1")),
                  "rolling[0].load_tolerance: must be > 0 and < 0.1 (got 0.1)");
  EXPECT_CONTAINS(error_of(rolling_with("load_tolerance = 0.0")),
                  "rolling[0].load_tolerance: must be > 0 and < 0.1 (got 0)");
  text = rolling_with("friction = 0.0");
  EXPECT_EQ(error_of(text), where(text, "0.0\n") + "rolling[0].friction: must be > 0 (got 0)");
  EXPECT_CONTAINS(error_of(rolling_with("friction = 5.5")), "rolling[0].friction: must be ≤ 5 (got 5.5)");
  EXPECT_CONTAINS(error_of(rolling_with("friction = inf")),
                  "rolling[0].friction: must be a finite number (got inf)");
  EXPECT_EQ(error_of(rolling_with("friction = 5")), "(no error)");
  EXPECT_CONTAINS(error_of(rolling_with("reverse = 1")),
                  "rolling[0].reverse: must be true or false (got an "
                  "integer)");
}

TEST(CaseReaderRolling, SupportAsForFootprints) {
  std::string text = tyre_with(
      "[[rolling]]\nname = \"r\"\nsupport = { kind = \"drum\", diameter = 0.0 }\n"
      "states = [{ state = \"free\" }]\n");
  EXPECT_EQ(error_of(text), where(text, "0.0 }") + "rolling[0].support.diameter: must be > 0 (got 0)");
  EXPECT_CONTAINS(error_of(tyre_with("[[rolling]]\nname = \"r\"\nstates = [{ state = \"free\" }]\n")),
                  "rolling[0].support: missing; expected a table");
  EXPECT_CONTAINS(
      error_of(tyre_with("[[rolling]]\nname = \"r\"\nsupport = { kind = \"plane\", diameter = 1 }\n"
                         "states = [{ state = \"free\" }]\n")),
      "rolling[0].support.diameter: not allowed for kind \"plane\"");
}

TEST(CaseReaderRolling, SurfaceMustNotChangeAlongY) {
  std::string text = tyre_with(
      "[[rolling]]\nname = \"r\"\nsupport = { kind = \"surface\", terms = [\n"
      "  { coefficient = 1e-4, x_power = 2 },\n  { coefficient = 1e-6, x_power = 1, y_power = 1 } ] }\n"
      "states = [{ state = \"free\" }]\n");
  EXPECT_EQ(error_of(text), where(text, "1 } ]") +
                                "rolling[0].support.terms[1].y_power: must be 0 where the coefficient is not "
                                "(got 1): steady rolling needs a road that does not change along y");
  // the general surface checks come first
  EXPECT_CONTAINS(
      error_of(tyre_with("[[rolling]]\nname = \"r\"\nsupport = { kind = \"surface\", terms = [] }\n"
                         "states = [{ state = \"free\" }]\n")),
      "rolling[0].support.terms: a surface needs at least one term");
}

TEST(CaseReaderRolling, NamesAreUniqueAmongAllStudies) {
  std::string text = example_text() +
                     "\n[[rolling]]\nname = \"footprint_3700N\"\nsupport = { kind = \"plane\" }\n"
                     "states = [{ state = \"free\" }]\n";
  EXPECT_EQ(error_of(text), where(text, "\"footprint_3700N\"\nsupport = { kind = \"plane\" }\nstates") +
                                "rolling[3].name: duplicate name \"footprint_3700N\" (already used by "
                                "footprint[0].name); load curves, footprints and rolling studies need "
                                "distinct names");
  EXPECT_CONTAINS(error_of(example_text() + "\n[[rolling]]\nname = \"drum\"\nsupport = { kind = \"plane\" }\n"
                                            "states = [{ state = \"free\" }]\n"),
                  "rolling[3].name: duplicate name \"drum\" (already used by load_curve[1].name)");
  EXPECT_CONTAINS(error_of(tyre_with("[[rolling]]\nname = \"a\"\nsupport = { kind = \"plane\" }\n"
                                     "states = [{ state = \"free\" }]\n"
                                     "[[rolling]]\nname = \"a\"\nsupport = { kind = \"plane\" }\n"
                                     "states = [{ state = \"free\" }]\n")),
                  "rolling[1].name: duplicate name \"a\" (already used by rolling[0].name)");
  EXPECT_CONTAINS(error_of(tyre_with("[[rolling]]\nname = \"slip.5\"\nsupport = { kind = \"plane\" }\n"
                                     "states = [{ state = \"free\" }]\n")),
                  "rolling[0].name: may contain only letters A-Z a-z, digits 0-9, '_' and '-'");
  EXPECT_CONTAINS(error_of(tyre_with("[[rolling]]\nsupport = { kind = \"plane\" }\n")),
                  "rolling[0].name: missing; expected a string ([A-Za-z0-9_-], unique among all studies)");
}

TEST(CaseReaderRolling, ValidateCaseRunsTheSameChecks) {
  Case good = read_case(kExample);
  RollingStudy r;
  r.name = "rolling";
  r.states = {
      {Kind::free, "free"}, {Kind::given_slip, "slip_0.05", 0.05}, {Kind::given_radius, "r", 0.0, 280.0}};
  good.rolling = {r};
  const auto error = case_test::validation_error_of;
  const std::string file = kExample.string() + ": ";
  EXPECT_EQ(error(good), "(no error)");

  Case c = good;
  c.rolling[0].states[1].slip = -1.5;
  EXPECT_EQ(error(c), file + "rolling[0].states[1].slip: must be > -1 (got -1.5)");
  c = good;
  c.rolling[0].states[0].slip = -1.5;  // a free state has no slip: not checked
  EXPECT_EQ(error(c), "(no error)");
  c = good;
  c.rolling[0].states[2].rolling_radius = 0.0;
  EXPECT_EQ(error(c), file + "rolling[0].states[2].rolling_radius: must be > 0 (got 0)");
  c = good;
  c.rolling[0].states[2].name = "";
  EXPECT_CONTAINS(error(c), file + "rolling[0].states[2].name: must not be empty");
  c = good;
  c.rolling[0].states[2].name = "free";
  EXPECT_CONTAINS(error(c), file + "rolling[0].states[2].name: duplicate state name \"free\"");
  c = good;
  c.rolling[0].states.clear();
  EXPECT_CONTAINS(error(c), file + "rolling[0]: needs states or a sweep");
  c.rolling[0].sweep = SlipSweep{0.2, 0.1, 5};
  EXPECT_EQ(error(c), file + "rolling[0].sweep.to: must be greater than from = 0.2 (got 0.1)");
  c = good;
  c.rolling[0].friction = 6.0;
  EXPECT_EQ(error(c), file + "rolling[0].friction: must be ≤ 5 (got 6)");
  c = good;
  c.rolling[0].load_tolerance = 0.5;
  EXPECT_EQ(error(c), file + "rolling[0].load_tolerance: must be > 0 and < 0.1 (got 0.5)");
  c = good;
  c.rolling[0].name = "plane";
  EXPECT_CONTAINS(error(c), file +
                                "rolling[0].name: duplicate name \"plane\" (already used by "
                                "load_curve[0].name)");
  c = good;
  c.rolling[0].support.kind = SupportDescription::Kind::surface;
  c.rolling[0].support.terms = {{1e-4, 2, 0}, {1e-6, 0, 2}};
  EXPECT_CONTAINS(error(c), file + "rolling[0].support.terms[1].y_power: must be 0 where the coefficient");
}

}  // namespace
}  // namespace tirefem
