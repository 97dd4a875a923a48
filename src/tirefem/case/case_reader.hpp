#pragma once
// Reads a case from TOML (layout: examples/175-70R13.toml, which documents every section). Every error
// is a CaseError whose message names the file, the line and column where known, the full dotted field path
// and what was expected, e.g.
//   case.toml:41:7: tyre.interlayer.thickness.value[3]: must be > 0 (got -1)
// Array indices in paths count from 0. Unknown keys are errors (typos).
#include <filesystem>
#include <stdexcept>
#include <string_view>

#include "tirefem/case/case.hpp"

namespace tirefem {

class CaseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads, parses and validates; the last zone's s_end is snapped to the profile's arc length when within
// 1 mm of it.
Case read_case(const std::filesystem::path& file);
Case parse_case(std::string_view toml_text, const std::filesystem::path& name_for_messages);

// The value and consistency checks of parse_case, for a Case built in code (messages without lines).
void validate_case(const Case& c);

// Tolerance for the last zone's end against the profile's arc length, mm.
inline constexpr double kZoneEndTolerance = 1.0;

}  // namespace tirefem
