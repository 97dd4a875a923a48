// The case reader refuses what cannot be solved (issue 10): self-intersecting and inside-out profiles,
// drums smaller than the tyre or absurdly large, meshes and point counts beyond the machine, state and
// study names that are not plain file names, rolling radii implying a refused slip, and values outside
// the plausibility bounds; and keys only rolling uses are required only by rolling studies. Every message
// names the field.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"
#include "tirefem/case/case_reader.hpp"
#include "tirefem/case/mesh_size_estimate.hpp"
#include "tirefem/case/profile_reader.hpp"
#include "tirefem/tyre/meridian_profile.hpp"

namespace tirefem {
namespace {

using namespace case_test;
using case_reading::profile_cavity_area;

// The example with its profile points replaced by `points` (the profile is checked first, so the rest of
// the tyre need not fit the new profile).
std::string with_profile(std::string_view points) {
  std::string text = example_text();
  const auto start = text.find("points = [");
  const auto end = text.find("]\n\n", start);
  text.replace(start, end + 1 - start, fmt::format("points = [{}]", points));
  return text;
}

// The example's tyre with one rolling study on the plane with `states`.
std::string rolling_states(std::string_view states) {
  return tyre_with(fmt::format("[[rolling]]\nname = \"r\"\nsupport = {{ kind = \"plane\" }}\nstates = [{}]\n", states));
}

// The example's outer radius: r(0) + h(0) + hp(0) = 272 + 3 + 10 mm.
constexpr double kOuterRadius = 285.0;

TEST(CaseReaderChecks, ProfileMustNotCrossItself) {
  // a curl, turning less than 90° at every point, whose last segment crosses its second
  const std::string curl = "[0, 272], [40, 270], [70, 255], [80, 230], [72, 205], [50, 195], [35, 210], [38, 240]";
  EXPECT_CONTAINS(error_of(with_profile(curl + ", [50, 280]")),
                  "tyre.profile.points[7]: the segment points[7]–points[8] crosses or touches points[1]–points[2]: "
                  "the carcass line must not cross itself");
  // ending on the second segment (touching), and on an earlier point
  EXPECT_CONTAINS(error_of(with_profile(curl + ", [55, 262.5]")),
                  "tyre.profile.points[7]: the segment points[7]–points[8] crosses or touches points[1]–points[2]");
  EXPECT_CONTAINS(error_of(with_profile(curl + ", [40, 270]")),
                  "tyre.profile.points[7]: the segment points[7]–points[8] crosses or touches points[0]–points[1]");
  // the curl without its last segment is a simple line (the zones do not fit it, which is checked next)
  EXPECT_CONTAINS(error_of(with_profile(curl)), "tyre.zones[");
  EXPECT_CONTAINS(error_of(with_profile("[0, 272], [40, 268], [40, 268], [60, 200]")),
                  "tyre.profile.points[2]: same point as points[1]");
  EXPECT_CONTAINS(error_of(with_profile("[0, 272], [0, 250], [60, 200]")),
                  "tyre.profile.points[1]: only the first point may lie on the equator");
}

TEST(CaseReaderChecks, TheSmoothCurveMustNotCrossItselfNorTheEquator) {
  // the points do not cross, but the spline through them overshoots across the first segment
  const std::string hook =
      "[0, 272], [40, 270], [70, 255], [80, 230], [72, 205], [50, 195], [35, 210], [30, 240], [26, 265], [5, 271.55]";
  EXPECT_CONTAINS(error_of(with_profile(hook)),
                  "tyre.profile.points[8]: the smooth curve through the points crosses itself between points[8]–"
                  "points[9] and points[0]–points[1]");
  // the same points a little further from the first segment: no crossing (the zones then do not fit)
  EXPECT_CONTAINS(error_of(with_profile(
                      "[0, 272], [40, 270], [70, 255], [80, 230], [72, 205], [50, 195], [35, 210], [30, 240], [26, 265], "
                      "[5, 268]")),
                  "tyre.zones[");
  // steeply down, then sideways: the spline bulges to x < 0 near the crown
  EXPECT_CONTAINS(error_of(with_profile("[0, 272], [0.2, 250], [40, 245], [60, 200]")),
                  "tyre.profile.points[0]: the smooth curve through the points reaches x = -1.27 between points[0] and "
                  "points[1]: it crosses the equator");
}

TEST(CaseReaderChecks, TheOuterFaceMustNotFoldInAConcaveBend) {
  Case c = read_case(kExample);
  // an S-shaped carcass line: a concave bend of ~27 mm radius around (62, 244)
  c.tyre.profile = {{0, 272}, {20, 271}, {40, 266}, {50, 258}, {55, 250}, {62, 244},
                    {72, 240}, {80, 232}, {82, 220}, {78, 205}, {70, 190}};
  c.tyre.zones.resize(1);
  c.tyre.zones[0].s_end = MeridianProfile(c.tyre.profile).length();
  c.tyre.interlayer_thickness = Table::constant(3.0);
  EXPECT_EQ(validation_error_of(c), "(no error)");
  c.tyre.interlayer_thickness = Table::constant(60.0);
  const std::string e = validation_error_of(c);
  EXPECT_CONTAINS(e, ": tyre.interlayer.thickness: h = 60 mm at s = ");
  EXPECT_CONTAINS(e, "the outer face would fold over");
  // the example's carcass line is convex: even the thickest plausible interlayer does not fold it
  Case thick = read_case(kExample);
  thick.tyre.interlayer_thickness = Table::constant(100.0);
  EXPECT_EQ(validation_error_of(thick).find("fold"), std::string::npos) << validation_error_of(thick);
}

TEST(CaseReaderChecks, ProfileMustNotBeInsideOut) {
  // the bead above the crown: the cavity closed by the rim line lies on the normal's side
  const std::string e = error_of(with_profile("[0, 185], [40, 190], [70, 230], [75, 272]"));
  EXPECT_CONTAINS(e, "tyre.profile.points: the profile is inside out");
  EXPECT_CONTAINS(e, "must be < 0");
  const Case c = read_case(kExample);
  EXPECT_LT(profile_cavity_area(c.tyre.profile), -1000.0);
  EXPECT_GT(profile_cavity_area({{0, 185}, {40, 190}, {70, 230}, {75, 272}}), 1000.0);
  // a right-handed square cavity: exactly −(60 × 60)
  EXPECT_DOUBLE_EQ(profile_cavity_area({{0, 260}, {60, 260}, {60, 200}}), -3600.0);
  EXPECT_TRUE(case_reading::segments_meet({0, 0}, {2, 2}, {0, 2}, {2, 0}));
  EXPECT_TRUE(case_reading::segments_meet({0, 0}, {2, 0}, {1, 0}, {1, 5}));   // touching
  EXPECT_FALSE(case_reading::segments_meet({0, 0}, {2, 0}, {3, 0}, {4, 0}));  // collinear, apart
  EXPECT_FALSE(case_reading::segments_meet({0, 0}, {2, 0}, {0, 1}, {2, 1}));
}

TEST(CaseReaderChecks, DrumsMustBeTestDrums) {
  const std::string drum = "support = { kind = \"drum\", diameter = 1830.0 }   #";
  auto with_drum = [&](double d) { return edited(drum, fmt::format("support = {{ kind = \"drum\", diameter = {} }}   #", d)); };
  for (double d : {0.001, 1.0, 569.0}) {
    SCOPED_TRACE(d);
    EXPECT_CONTAINS(error_of(with_drum(d)),
                    "load_curve[1].support.diameter: must be at least the tyre's outer diameter, 2 × 285.0 = 570.0 mm");
  }
  EXPECT_EQ(error_of(with_drum(2 * kOuterRadius)), "(no error)");
  EXPECT_EQ(error_of(with_drum(1e5)), "(no error)");
  EXPECT_CONTAINS(error_of(with_drum(1e300)), "load_curve[1].support.diameter: must be ≤ 100000 mm");
  EXPECT_CONTAINS(error_of(with_drum(1.0000001e5)), "load_curve[1].support.diameter: must be ≤ 100000 mm");
  EXPECT_CONTAINS(error_of(tyre_with("[[footprint]]\nname = \"f\"\nsupport = { kind = \"drum\", diameter = 100.0 }\n")),
                  "footprint[0].support.diameter: must be at least the tyre's outer diameter");
  EXPECT_CONTAINS(error_of(tyre_with("[[rolling]]\nname = \"r\"\nsupport = { kind = \"drum\", diameter = 3e5 }\n"
                                     "states = [{ state = \"free\" }]\n")),
                  "rolling[0].support.diameter: must be ≤ 100000 mm");
  Case c = read_case(kExample);
  c.load_curves[1].support.drum_diameter = 400.0;
  EXPECT_CONTAINS(validation_error_of(c), "load_curve[1].support.diameter: must be at least");
}

TEST(CaseReaderChecks, MeshSizeEstimate) {
  MeshSettings m;  // 120 × 46 half model: the reference figure
  MeshSizeEstimate e = estimate_mesh_size(m);
  EXPECT_EQ(e.dof, 33840.0);
  EXPECT_EQ(e.elements, 120.0 * 46.0);
  EXPECT_DOUBLE_EQ(e.factor_nonzeros, 2 * 5.8e6);
  EXPECT_LT(e.bytes, 1e9);
  m.half_model = false;  // bead to bead: 92 elements, 93 node rings
  e = estimate_mesh_size(m);
  EXPECT_EQ(e.dof, 6.0 * 120 * 93);
  EXPECT_GT(e.factor_nonzeros, 2 * 2 * 5.8e6);  // more than linear growth
  m.circumferential_elements = 10000000;
  EXPECT_GT(estimate_mesh_size(m).bytes, 1e13);
  EXPECT_GT(physical_memory_bytes(), 1e8);
}

TEST(CaseReaderChecks, MeshesBeyondTheMachineAreRefusedWithTheEstimate) {
  const std::string e = error_of(edited("circumferential_elements = 120", "circumferential_elements = 10000000"));
  EXPECT_CONTAINS(e, "mesh.circumferential_elements: a 10000000 × 46 half model has 4.6e+08 elements and 2.82e+09 DOF;");
  EXPECT_CONTAINS(e, "GiB, this machine has");
  EXPECT_CONTAINS(error_of(edited("meridional_elements = 46", "meridional_elements = 1000000000")),
                  "mesh.meridional_elements: a 120 × 1000000000 half model");
  EXPECT_CONTAINS(error_of(edited("circumferential_elements = 120", "circumferential_elements = 10001")),
                  "mesh.circumferential_elements: must be ≤ 10000 (got 10001;");
  EXPECT_CONTAINS(error_of(edited("meridional_elements = 46", "meridional_elements = 2001")),
                  "mesh.meridional_elements: must be ≤ 2000 (got 2001;");
  EXPECT_CONTAINS(error_of(tyre_with("[[rolling]]\nname = \"r\"\nsupport = { kind = \"plane\" }\n"
                                     "mesh = { circumferential_elements = 50000000 }\nstates = [{ state = \"free\" }]\n")),
                  "rolling[0].mesh.circumferential_elements: a 50000000 × 46 half model");
}

TEST(CaseReaderChecks, PointCountsAreCapped) {
  const std::string points = "max_deflection = 40.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"";
  EXPECT_CONTAINS(error_of(edited(points, "max_deflection = 40.0\npoints = 1000000\n\n[[load_curve]]\nname = \"drum\"")),
                  "load_curve[0].points: must be ≤ 1000 (got 1000000)");
  EXPECT_CONTAINS(error_of(edited(points, "max_deflection = 40.0\npoints = 1001\n\n[[load_curve]]\nname = \"drum\"")),
                  "load_curve[0].points: must be ≤ 1000 (got 1001)");
  EXPECT_EQ(error_of(edited(points, "max_deflection = 40.0\npoints = 1000\n\n[[load_curve]]\nname = \"drum\"")),
            "(no error)");
  std::string many;
  for (int i = 0; i <= 2000; ++i) many += fmt::format("{}[{}, {}]", i ? ", " : "", 0.01 * i, 272.0 - 1e-4 * i);
  EXPECT_CONTAINS(error_of(with_profile(many)), "tyre.profile.points: at most 2000 points (got 2001)");
}

TEST(CaseReaderChecks, DeflectionStaysAboveTheBead) {
  // section height: 285 − 185 (the bead, the profile's lowest point) = 100 mm
  const std::string points = "max_deflection = 40.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"";
  EXPECT_CONTAINS(error_of(edited(points, "max_deflection = 395.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"")),
                  "load_curve[0].max_deflection: must be less than the tyre's section height, 100.0 mm");
  EXPECT_CONTAINS(error_of(edited(points, "max_deflection = 100.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"")),
                  "load_curve[0].max_deflection: must be less than");
  EXPECT_EQ(error_of(edited(points, "max_deflection = 99.0\npoints = 20\n\n[[load_curve]]\nname = \"drum\"")),
            "(no error)");
}

TEST(CaseReaderChecks, NamesArePlainFileNames) {
  for (const char* name : {"..", ".", ".hidden", ".x+1"}) {
    SCOPED_TRACE(name);
    EXPECT_CONTAINS(error_of(rolling_states(fmt::format("{{ state = \"free\", name = \"{}\" }}", name))),
                    "rolling[0].states[0].name: must not start with '.'");
  }
  EXPECT_CONTAINS(error_of(rolling_states("{ state = \"free\", name = \"../x\" }")),
                  "rolling[0].states[0].name: may contain only letters");
  EXPECT_CONTAINS(error_of(rolling_states("{ state = \"free\", name = \"a\\\\b\" }")),
                  "rolling[0].states[0].name: may contain only letters");
  EXPECT_EQ(error_of(rolling_states("{ state = \"free\", name = \"slip.5+\" }")), "(no error)");
  EXPECT_CONTAINS(error_of(rolling_states(fmt::format("{{ state = \"free\", name = \"{}\" }}", std::string(101, 'x')))),
                  "rolling[0].states[0].name: must have at most 100 characters (got 101)");
  EXPECT_EQ(error_of(rolling_states(fmt::format("{{ state = \"free\", name = \"{}\" }}", std::string(100, 'x')))),
            "(no error)");
  EXPECT_CONTAINS(error_of(tyre_with(fmt::format("[[footprint]]\nname = \"{}\"\nsupport = {{ kind = \"plane\" }}\n",
                                                 std::string(101, 'f')))),
                  "footprint[0].name: must have at most 100 characters");
  EXPECT_CONTAINS(error_of(tyre_with("[[footprint]]\nname = \"..\"\nsupport = { kind = \"plane\" }\n")),
                  "footprint[0].name: may contain only letters A-Z a-z, digits 0-9, '_' and '-' (got \"..\")");
  Case c = read_case(kExample);
  RollingStudy r;
  r.name = "r";
  r.states = {{RollingStateSpec::Kind::free, ".."}};
  c.rolling = {r};
  EXPECT_CONTAINS(validation_error_of(c), "rolling[0].states[0].name: must not start with '.'");
}

TEST(CaseReaderChecks, GivenRadiusMustImplyAnAcceptedSlip) {
  auto radius = [](double rk) {
    return rolling_states(fmt::format("{{ state = \"given_radius\", rolling_radius = {} }}", rk));
  };
  const std::string e = error_of(radius(1e9));
  EXPECT_CONTAINS(e, "rolling[0].states[0].rolling_radius: implies a slip κ = R/Rk − 1 = -0.999999715 with R ≈ 285.0 mm");
  EXPECT_CONTAINS(e, "the slip must be in [-0.99, 10], so Rk in [25.9, 28500] mm");
  EXPECT_CONTAINS(error_of(radius(25.0)), "rolling[0].states[0].rolling_radius: implies a slip κ = R/Rk − 1 = 10.4");
  EXPECT_CONTAINS(error_of(radius(29000.0)), "rolling[0].states[0].rolling_radius: implies a slip");
  EXPECT_EQ(error_of(radius(26.0)), "(no error)");
  EXPECT_EQ(error_of(radius(28000.0)), "(no error)");
  EXPECT_EQ(error_of(radius(280.0)), "(no error)");
  EXPECT_CONTAINS(error_of(radius(-280.0)), "rolling[0].states[0].rolling_radius: must be > 0 (got -280)");
}

// Each plausibility bound: the field named, the bound stated, and a value just inside accepted.
TEST(CaseReaderChecks, PlausibilityBounds) {
  struct Case_ {
    std::string_view from, to, message;
  };
  const Case_ cases[] = {
      {"cord_modulus = 3500.0", "cord_modulus = 1e30",
       "tyre.plies.carcass.cord_modulus: must be in [0.001, 1e+06] MPa (the plausibility bound for any real tyre; got "
       "1e+30)"},
      {"cord_modulus = 3500.0", "cord_modulus = 1e-4", "tyre.plies.carcass.cord_modulus: must be in [0.001, 1e+06] MPa"},
      {"rubber_modulus = 4.0", "rubber_modulus = 2e6", "tyre.plies.carcass.rubber_modulus: must be in [0.001, 1e+06] MPa"},
      {"thickness = 1.0\nrubber_modulus = 4.0", "thickness = 1e6\nrubber_modulus = 4.0",
       "tyre.plies.carcass.thickness: must be in [0.01, 100] mm"},
      {"E = 3.0", "E = 1e7", "tyre.zones[2].outer.rubber.E: must be in [0.001, 1e+06] MPa"},
      {"E = 3.0, nu = 0.49, thickness = 3.0", "E = 3.0, nu = 0.49, thickness = 0.001",
       "tyre.zones[2].outer.rubber.thickness: must be in [0.01, 100] mm"},
      {"core_shear_modulus = 0.8", "core_shear_modulus = 1e9", "tyre.zones[2].core_shear_modulus: must be in [0.001, 1e+06] MPa"},
      {"core_shear_modulus = 0.8\ncore_normal_modulus = 100.0", "core_shear_modulus = 0.8\ncore_normal_modulus = 1e-5",
       "tyre.zones[2].core_normal_modulus: must be in [0.001, 1e+06] MPa"},
      {"value = [3.0,  3.0,  6.0,  5.0,", "value = [3.0,  3.0,  6.0,  1e6,",
       "tyre.interlayer.thickness.value[3]: must be in [0.01, 100] mm"},
      {"value = [10.0, 10.0, 8.0, 8.0]", "value = [10.0, 101, 8.0, 8.0]", "tyre.tread.height.value[1]: must be in [0, 100] mm"},
      {"stiffness = 1.0", "stiffness = 1e9", "tyre.tread.stiffness: must be in [0.001, 100] N/mm³"},
      {"shear_modulus = 0.55", "shear_modulus = 1e9", "tyre.tread.shear_modulus: must be in [0.001, 1e+06] MPa"},
      {"pressure = 0.2", "pressure = 2.5", "inflation.pressure: must be in [0, 2] MPa"},
      {kBeltFace, "outer = { stiffness = [[2e8, 0, 0], [0, 1e3, 0], [0, 0, 1e3]] }",
       "tyre.zones[0].outer.stiffness[0][0]: must be ≤ 1e+08 N/mm"},
      {kBeltFace, "outer = { plies = [\"belt1\", \"belt2\"], bending_stiffness = [100.0, 2e9] }",
       "tyre.zones[0].outer.bending_stiffness[1]: must be in [0, 1e+09] N·mm"},
  };
  for (const Case_& c : cases) {
    SCOPED_TRACE(c.to);
    EXPECT_CONTAINS(error_of(edited(c.from, c.to)), c.message);
  }
  EXPECT_CONTAINS(error_of(edited("target_load = 3700.0", "target_load = 1e300")),
                  "footprint[0].target_load: must be ≤ 1e+06 N (the plausibility bound for any real tyre; got 1e+300)");
  EXPECT_CONTAINS(error_of(edited("max_contact_iterations = 30", "max_contact_iterations = 1000000")),
                  "contact.max_contact_iterations: must be ≤ 1000 (got 1000000)");
  EXPECT_CONTAINS(error_of(tyre_with("[contact]\nmax_newton_iterations = 1001\n")),
                  "contact.max_newton_iterations: must be ≤ 1000 (got 1001)");
  EXPECT_CONTAINS(error_of(tyre_with("[contact]\nmax_state_iterations = 0\n")),
                  "contact.max_state_iterations: must be ≥ 1 (got 0)");
  EXPECT_CONTAINS(error_of(edited("max_newton_iterations = 25\nresidual_tolerance = 1e-8      # Newton",
                                  "max_newton_iterations = 5000\nresidual_tolerance = 1e-8      # Newton")),
                  "inflation.max_newton_iterations: must be ≤ 1000 (got 5000)");
  EXPECT_EQ(error_of(edited("target_load = 3700.0", "target_load = 1e6")), "(no error)");
  // the ends of the bounds are accepted
  EXPECT_EQ(error_of(edited("pressure = 0.2", "pressure = 2.0")), "(no error)");
  EXPECT_EQ(error_of(edited("stiffness = 1.0", "stiffness = 100.0")), "(no error)");
  EXPECT_EQ(error_of(edited("core_shear_modulus = 0.8", "core_shear_modulus = 1e6")), "(no error)");
  EXPECT_EQ(error_of(edited("value = [10.0, 10.0, 8.0, 8.0]", "value = [10.0, 100, 0, 8.0]")), "(no error)");
  // a disabled inflation may have zero pressure, not an implausible one
  auto disabled = [](std::string_view pressure) {
    std::string text = edited("pressure = 0.2", pressure);
    text.replace(text.find("enabled = true"), 14, "enabled = false");
    return text;
  };
  EXPECT_EQ(error_of(disabled("pressure = 0.0")), "(no error)");
  EXPECT_CONTAINS(error_of(disabled("pressure = 5.0")), "inflation.pressure: must be in [0, 2] MPa");
}

TEST(CaseReaderChecks, TreadShearModulusOnlyForRolling) {
  const std::string text = tyre_with("");
  const auto at = text.find("shear_modulus = 0.55\n");
  ASSERT_NE(at, std::string::npos);
  std::string without = text;
  without.erase(at, std::string("shear_modulus = 0.55\n").size());
  const Case c = parse_case(without, "case.toml");
  EXPECT_EQ(c.tyre.tread_shear_modulus, 0.0);
  const std::string rolling = without + "[[rolling]]\nname = \"r\"\nsupport = { kind = \"plane\" }\nstates = [{ state = \"free\" }]\n";
  const std::string e = error_of(rolling);
  EXPECT_EQ(e.rfind("case.toml:", 0), 0u) << e;
  EXPECT_CONTAINS(e, ": tyre.tread.shear_modulus: missing; expected a number (MPa), the tread rubber's shear modulus: "
                     "the rolling study r needs it");
  // a case built in code: checked when a study rolls or when it is set
  Case built = read_case(kExample);
  built.rolling.clear();
  built.tyre_tests.clear();
  built.tyre.tread_shear_modulus = 0.0;
  EXPECT_EQ(validation_error_of(built), "(no error)");
  RollingStudy r;
  r.name = "r";
  r.states = {{RollingStateSpec::Kind::free, "free"}};
  built.rolling = {r};
  EXPECT_CONTAINS(validation_error_of(built), "tyre.tread.shear_modulus: must be > 0 (got 0)");
  built.rolling.clear();
  built.tyre_tests.clear();
  built.tyre.tread_shear_modulus = -1.0;
  EXPECT_CONTAINS(validation_error_of(built), "tyre.tread.shear_modulus: must be > 0 (got -1)");
}

}  // namespace
}  // namespace tirefem
