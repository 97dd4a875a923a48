#pragma once
// Helpers of the case reader's unit tests (case_reader_test.cpp, case_reader_studies_test.cpp,
// case_reader_rolling*_test.cpp): the example case as text, edits of it, the error that parsing a text or
// validating a case gives and the "case.toml:LINE:COL: " an error starts with.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "tirefem/case/case_reader.hpp"

namespace tirefem::case_test {

inline const std::filesystem::path kExample =
    std::filesystem::path(TIREFEM_SOURCE_DIR) / "examples/175-70R13.toml";

// The example's belt face, as its text stands (tests edit it).
inline constexpr std::string_view kBeltFace =
    "outer = { plies = [\"belt1\", \"belt2\"], bending_stiffness = [100.0, 300.0] }";

inline std::string example_text() {
  std::ifstream in(kExample);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The example with one edit; fails the test if `from` is not in it exactly once.
inline std::string edited(std::string_view from, std::string_view to) {
  std::string text = example_text();
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "not unique: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// The example up to (not including) its studies, i.e. the tyre, mesh and inflation only, plus `studies`.
inline std::string tyre_with(std::string_view studies) {
  std::string text = example_text();
  const auto at = text.find("# Tread–road contact");
  EXPECT_NE(at, std::string::npos);
  text.erase(at);
  return text + std::string(studies);
}

// A rolling study on the plane with one free state, plus `extra` lines (after the support line).
inline std::string rolling_with(std::string_view extra,
                                std::string_view states = "states = [{ state = \"free\" }]") {
  return tyre_with(
      fmt::format("[[rolling]]\nname = \"r\"\nsupport = {{ kind = \"plane\" }}\n{}\n{}\n", extra, states));
}
// One state table in a rolling study.
inline std::string state(std::string_view table) { return rolling_with("", fmt::format("states = [{}]", table)); }

// The message of the CaseError that parsing `text` (as "case.toml") throws; "(no error)" if none.
inline std::string error_of(const std::string& text) {
  try {
    parse_case(text, "case.toml");
  } catch (const CaseError& e) {
    return e.what();
  }
  return "(no error)";
}

// The message of the CaseError that validate_case(c) throws; "(no error)" if none.
inline std::string validation_error_of(const Case& c) {
  try {
    validate_case(c);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "(no error)";
}

// "case.toml:LINE:COL: " of the first occurrence of `needle` in `text` at or after offset `from`; fails
// the test if there is none.
inline std::string where(const std::string& text, std::string_view needle, std::size_t from = 0) {
  const auto at = text.find(needle, from);
  EXPECT_NE(at, std::string::npos) << needle;
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  const auto col = at - (text.rfind('\n', at) + 1) + 1;
  return "case.toml:" + std::to_string(line) + ":" + std::to_string(col) + ": ";
}

}  // namespace tirefem::case_test

#define EXPECT_CONTAINS(haystack, needle) EXPECT_NE((haystack).find(needle), std::string::npos) << (haystack)
