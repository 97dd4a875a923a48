#pragma once
// Reader of PAC2002 / MF 5.2 `.tir` property files (TNO / Adams tyre property format).
//
// Accepted layout: `[SECTION]` headers; `KEY = value` lines with an optional trailing `$` or `!` comment;
// whole-line comments starting with `$` or `!`; strings in single or double quotes; tables (a `{...}`
// header followed by rows of numbers, e.g. [SHAPE]) skipped. Keys are case-insensitive. Every numeric key
// of `coefficient_table()` is read into `MagicFormulaCoefficients`; a missing one keeps its neutral value;
// a key the table does not know is kept in `TirFile::other_entries`. The units must be SI (meter, newton,
// radian(s), kg/kilogram, second): the evaluator does not convert.
#include <filesystem>
#include <stdexcept>
#include <string_view>

#include "tirefem/magic_formula/coefficients.hpp"

namespace tirefem {

// One line: "<file>:<line>: <KEY>: <what is wrong>".
class TirFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `source` names the text in error messages (usually the file name).
TirFile parse_tir(std::string_view text, std::string_view source);
TirFile read_tir_file(const std::filesystem::path& file);

}  // namespace tirefem
