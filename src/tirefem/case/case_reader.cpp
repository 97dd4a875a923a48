// The case reader: parses the TOML, reads each section with its own reader (tyre_reader, mesh_reader,
// settings_reader, study_reader, rolling_reader; shared helpers in toml_fields and field_checker), then
// runs the value checks of every section in file order.
#include "tirefem/case/case_reader.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tirefem/case/mesh_reader.hpp"
#include "tirefem/case/rolling_reader.hpp"
#include "tirefem/case/settings_reader.hpp"
#include "tirefem/case/study_reader.hpp"
#include "tirefem/case/toml_fields.hpp"
#include "tirefem/case/tyre_reader.hpp"
#include "tirefem/case/tyre_test_reader.hpp"
#include "tirefem/tyre/meridian_profile.hpp"

namespace tirefem {
namespace {

using namespace case_reading;

// Structure and types (missing fields, wrong types, unknown keys, unknown names) of the whole file.
Case read_root(TomlFields& f, const toml::table& root) {
  const toml::table& r =
      f.table(root, "", {"title", "tyre", "mesh", "inflation", "contact", "load_curve", "footprint", "rolling", "tyre_test"});
  Case c;
  if (const toml::node* v = f.get(r, "", "title")) c.title = f.string(*v, "title");
  const TyreRead tyre = read_tyre(f, f.need(r, "", "tyre", "a table [tyre]"), "tyre");
  c.tyre = tyre.tyre;
  if (c.title.empty()) c.title = c.tyre.name;
  if (const toml::node* v = f.get(r, "", "mesh")) c.mesh = read_mesh(f, *v, "mesh", c.mesh);
  if (const toml::node* v = f.get(r, "", "inflation")) c.inflation = read_inflation(f, *v, "inflation");
  if (const toml::node* v = f.get(r, "", "contact")) c.contact = read_contact(f, *v, "contact");
  if (const toml::node* v = f.get(r, "", "load_curve")) {
    const toml::array& a = f.array(*v, "load_curve", "tables [[load_curve]]");
    for (std::size_t i = 0; i < a.size(); ++i) c.load_curves.push_back(read_load_curve(f, a[i], index("load_curve", i)));
  }
  if (const toml::node* v = f.get(r, "", "footprint")) {
    const toml::array& a = f.array(*v, "footprint", "tables [[footprint]]");
    for (std::size_t i = 0; i < a.size(); ++i) c.footprints.push_back(read_footprint(f, a[i], index("footprint", i)));
  }
  if (const toml::node* v = f.get(r, "", "rolling")) {
    const toml::array& a = f.array(*v, "rolling", "tables [[rolling]]");
    for (std::size_t i = 0; i < a.size(); ++i) c.rolling.push_back(read_rolling(f, a[i], index("rolling", i), c.mesh));
  }
  if (const toml::node* v = f.get(r, "", "tyre_test")) {
    const toml::array& a = f.array(*v, "tyre_test", "tables [[tyre_test]]");
    for (std::size_t i = 0; i < a.size(); ++i)
      c.tyre_tests.push_back(read_tyre_test(f, a[i], index("tyre_test", i), c.mesh));
  }
  // Keys only some studies use are required only when such a study is there.
  if ((!c.rolling.empty() || !c.tyre_tests.empty()) && !tyre.shear_modulus_given)
    f.fail("tyre.tread.shear_modulus",
           fmt::format("missing; expected a number (MPa), the tread rubber's shear modulus: the {} study {} "
                       "needs it",
                       c.rolling.empty() ? "tyre_test" : "rolling",
                       c.rolling.empty() ? c.tyre_tests.front().name : c.rolling.front().name));
  return c;
}

// The value and consistency checks, section by section.
void check_case(const FieldChecker& checker, const Case& c) {
  const TyreDescription& t = c.tyre;
  check_tyre(checker, t, !c.rolling.empty() || !c.tyre_tests.empty());
  TyreScale scale;
  scale.outer_radius = tyre_outer_radius(t);
  const auto lowest = std::min_element(t.profile.begin(), t.profile.end(),
                                       [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.y() < b.y(); });
  scale.section_height = scale.outer_radius - lowest->y();

  check_mesh(checker, c.mesh, "mesh", t.zones.size());
  for (std::size_t i = 0; i < c.rolling.size(); ++i)
    if (c.rolling[i].mesh) check_mesh(checker, *c.rolling[i].mesh, join(index("rolling", i), "mesh"), t.zones.size());
  for (std::size_t i = 0; i < c.tyre_tests.size(); ++i)
    if (c.tyre_tests[i].mesh)
      check_mesh(checker, *c.tyre_tests[i].mesh, join(index("tyre_test", i), "mesh"), t.zones.size());
  check_inflation(checker, c.inflation, "inflation");
  check_contact(checker, c.contact, "contact");

  std::map<std::string, std::string> names;  // study name -> path of the study that has it
  for (std::size_t i = 0; i < c.load_curves.size(); ++i) {
    const std::string p = index("load_curve", i);
    check_study_name(checker, c.load_curves[i].name, join(p, "name"), names);
    check_load_curve(checker, c.load_curves[i], p, scale);
  }
  for (std::size_t i = 0; i < c.footprints.size(); ++i) {
    const std::string p = index("footprint", i);
    check_study_name(checker, c.footprints[i].name, join(p, "name"), names);
    check_footprint(checker, c.footprints[i], p, scale);
  }
  for (std::size_t i = 0; i < c.rolling.size(); ++i) {
    const std::string p = index("rolling", i);
    check_study_name(checker, c.rolling[i].name, join(p, "name"), names);
    check_rolling(checker, c.rolling[i], p, scale, c.mesh.half_model);
  }
  for (std::size_t i = 0; i < c.tyre_tests.size(); ++i) {
    const std::string p = index("tyre_test", i);
    check_study_name(checker, c.tyre_tests[i].name, join(p, "name"), names);
    check_tyre_test(checker, c.tyre_tests[i], p, scale, c.mesh.half_model);
  }
}

// The last zone ends at the bead: snap its end to the profile's arc length (validated to be within 1 mm).
void snap_last_zone(Case& c) { c.tyre.zones.back().s_end = MeridianProfile(c.tyre.profile).length(); }

}  // namespace

Case parse_case(std::string_view toml_text, const std::filesystem::path& name_for_messages) {
  const std::string file = name_for_messages.string();
  toml::table root;
  try {
    root = toml::parse(toml_text, file);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw CaseError(fmt::format("{}:{}:{}: TOML syntax error: {}", file, b.line, b.column, e.description()));
  }
  TomlFields fields(file);
  Case c = read_root(fields, root);
  c.source = name_for_messages;
  check_case(fields.checker(), c);
  snap_last_zone(c);
  return c;
}

Case read_case(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CaseError(fmt::format("{}: cannot open the case file", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_case(text.str(), file);
}

void validate_case(const Case& c) {
  const std::string file = c.source.empty() ? std::string("case") : c.source.string();
  check_case(FieldChecker([&file](const std::string&) { return file; }), c);
}

}  // namespace tirefem
