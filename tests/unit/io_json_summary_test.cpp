// JSON summary: numbers stay numbers, nesting works, keys come out sorted, non-finite values are refused.
#include <fstream>
#include <limits>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "scratch_dir.hpp"
#include "tirefem/io/json_summary.hpp"

namespace tirefem {
namespace {
namespace fs = std::filesystem;

// A scratch folder of this file's own.
struct ScratchDir : test::ScratchDir {
  ScratchDir() : test::ScratchDir("io_json") {}
};
using test::read_file;

std::string without_whitespace(const std::string& text) {
  std::string out;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"' && (i == 0 || text[i - 1] != '\\')) in_string = !in_string;
    if (in_string || (c != ' ' && c != '\n')) out += c;
  }
  return out;
}

toml::table summary() {
  toml::array steps;
  steps.push_back(toml::table{{"lambda", 0.5}, {"iterations", 4}});
  steps.push_back(toml::table{{"lambda", 1.0}, {"iterations", 3}});
  return toml::table{
      {"tyre", "175-70R13"},
      {"converged", true},
      {"dof", 34000},
      {"Qz_N", 3500.25},
      {"inflation", toml::table{{"p_MPa", 0.2}, {"radial_growth_mm", 1.5}}},
      {"steps", steps},
      {"deflections_mm", toml::array{5.0, 10.0, 15.5}},
  };
}

TEST(IoJsonSummary, WritesNumbersNestingAndSortedKeys) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "summary.json";
  write_json(file, summary());
  const std::string text = read_file(file);
  const std::string flat = without_whitespace(text);
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(flat.find("\"Qz_N\":3500.25,"), std::string::npos) << text;  // a number, not "3500.25"
  EXPECT_NE(flat.find("\"dof\":34000,"), std::string::npos) << text;
  EXPECT_NE(flat.find("\"converged\":true,"), std::string::npos) << text;
  EXPECT_NE(flat.find("\"tyre\":\"175-70R13\""), std::string::npos) << text;
  EXPECT_NE(flat.find("\"inflation\":{\"p_MPa\":0.2"), std::string::npos) << text;
  EXPECT_NE(flat.find("\"radial_growth_mm\":1.5}"), std::string::npos) << text;
  EXPECT_NE(flat.find("\"steps\":[{\"iterations\":4,\"lambda\":0.5},{\"iterations\":3,\"lambda\":1.0}]"),
            std::string::npos)
      << text;
  EXPECT_NE(flat.find("\"deflections_mm\":[5.0,10.0,15.5]"), std::string::npos) << text;
  // toml::table is a sorted map: keys come out in byte order, not insertion order.
  EXPECT_EQ(flat.rfind("{\"Qz_N\":", 0), 0u) << text;
  EXPECT_LT(flat.find("\"converged\""), flat.find("\"deflections_mm\""));
  EXPECT_LT(flat.find("\"steps\""), flat.find("\"tyre\""));
}

TEST(IoJsonSummary, DoublesRoundTrip) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "precision.json";
  const double third = 1.0 / 3.0;
  write_json(file, toml::table{{"x", third}});
  const std::string flat = without_whitespace(read_file(file));
  const std::size_t colon = flat.find(':');
  EXPECT_EQ(std::stod(flat.substr(colon + 1)), third) << flat;
}

TEST(IoJsonSummary, NonFiniteValueNamesTheKey) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "bad.json";
  toml::table table = summary();
  table["steps"].as_array()->get(1)->as_table()->insert_or_assign("Qy_N",
                                                                  std::numeric_limits<double>::quiet_NaN());
  try {
    write_json(file, table);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("steps[1].Qy_N"), std::string::npos) << message;
    EXPECT_NE(message.find("bad.json"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(file));
  EXPECT_THROW(
      write_json(file, toml::table{{"a", toml::table{{"b", std::numeric_limits<double>::infinity()}}}}),
      std::invalid_argument);
}

TEST(IoJsonSummary, UnwritableFileNamesTheFile) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "missing" / "summary.json";
  try {
    write_json(file, summary());
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tirefem
