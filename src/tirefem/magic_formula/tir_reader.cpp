#include "tirefem/magic_formula/tir_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>

namespace tirefem {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

std::string upper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return out;
}

// The value text before a `$` or `!` comment that is not inside quotes.
std::string_view strip_comment(std::string_view value) {
  char quote = 0;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const char c = value[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '$' || c == '!') {
      return value.substr(0, i);
    }
  }
  return value;
}

bool is_quoted(std::string_view v) {
  return v.size() >= 2 && (v.front() == '\'' || v.front() == '"') && v.back() == v.front();
}

std::string unquote(std::string_view v) { return std::string(is_quoted(v) ? v.substr(1, v.size() - 2) : v); }

bool is_number_row(std::string_view line) {
  std::istringstream in{std::string(line)};
  std::string token;
  bool any = false;
  while (in >> token) {
    double value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc{} || end != token.data() + token.size()) return false;
    any = true;
  }
  return any;
}

class LineContext {
 public:
  LineContext(std::string_view source, int line) : source_(source), line_(line) {}
  [[noreturn]] void fail(std::string_view key, std::string_view what) const {
    throw TirFileError(fmt::format("{}:{}: {}: {}", source_, line_, key, what));
  }

 private:
  std::string_view source_;
  int line_;
};

double parse_number(std::string_view key, std::string_view value, const LineContext& where) {
  if (value.empty()) where.fail(key, "expected a number, got nothing");
  if (is_quoted(value)) where.fail(key, fmt::format("expected a number, got the string {}", value));
  std::string text(value);
  if (text.front() == '+') text.erase(0, 1);
  // Fortran-style exponents ("1.5D+03") appear in some older files.
  std::replace(text.begin(), text.end(), 'D', 'e');
  std::replace(text.begin(), text.end(), 'd', 'e');
  double number = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (ec != std::errc{} || end != text.data() + text.size())
    where.fail(key, fmt::format("expected a number, got '{}'", value));
  return number;
}

void check_si_unit(std::string_view key, const std::string& unit, const LineContext& where) {
  const std::string u = upper(unit);
  const bool ok = (key == "LENGTH" && (u == "METER" || u == "METRE" || u == "M")) ||
                  (key == "FORCE" && (u == "NEWTON" || u == "N")) ||
                  (key == "ANGLE" && (u == "RADIAN" || u == "RADIANS" || u == "RAD")) ||
                  (key == "MASS" && (u == "KG" || u == "KILOGRAM")) ||
                  (key == "TIME" && (u == "SECOND" || u == "SEC" || u == "S"));
  if (!ok) where.fail(key, fmt::format("unit '{}' is not supported (SI units only: meter, newton, radian, kg, second)", unit));
}

}  // namespace

TirFile parse_tir(std::string_view text, std::string_view source) {
  TirFile file;
  file.property_file_format.clear();
  file.tyre_side.clear();
  std::string section;
  bool in_table = false;
  int line_number = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view raw = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    const LineContext where(source, line_number);
    const std::string_view line = trim(raw);
    if (line.empty()) continue;
    if (line.front() == '!' || line.front() == '$') {
      constexpr std::string_view comment_tag = "! : COMMENT :";
      if (line.substr(0, comment_tag.size()) == comment_tag)
        file.header_comments.emplace_back(trim(line.substr(comment_tag.size())));
      continue;
    }
    if (line.front() == '[') {
      if (line.back() != ']') where.fail(line, "section header without closing ']'");
      section = upper(trim(line.substr(1, line.size() - 2)));
      in_table = false;
      continue;
    }
    if (line.front() == '{') {
      in_table = true;
      continue;
    }
    const auto equals = line.find('=');
    if (equals == std::string_view::npos) {
      if (in_table || is_number_row(line)) continue;
      where.fail(line, "expected 'KEY = value'");
    }
    const std::string key = upper(trim(line.substr(0, equals)));
    if (key.empty()) where.fail("(no key)", "a line starts with '='");
    const std::string_view value = trim(strip_comment(line.substr(equals + 1)));

    if (const CoefficientInfo* info = find_coefficient(key)) {
      file.coefficients.*(info->member) = parse_number(key, value, where);
      // MF 6.1 and 6.2 files (FITTYP 61, 62) share most keys with PAC2002 but not their formulas: read as
      // PAC2002 they would evaluate to other forces without a word.
      if (key == "FITTYP" && file.coefficients.FITTYP != 6 && file.coefficients.FITTYP != 21)
        where.fail(key, fmt::format("{} is not MF 5.2 / PAC2002 (FITTYP 6 or 21), the only version read here{}",
                                    value, file.coefficients.FITTYP == 61 || file.coefficients.FITTYP == 62
                                               ? fmt::format(" (it is MF 6.{})", file.coefficients.FITTYP - 60)
                                               : ""));
    } else if (key == "FILE_TYPE") {
      file.file_type = unquote(value);
    } else if (key == "FILE_FORMAT") {
      file.file_format = unquote(value);
    } else if (key == "PROPERTY_FILE_FORMAT") {
      file.property_file_format = unquote(value);
    } else if (key == "TYRESIDE") {
      file.tyre_side = unquote(value);
    } else if (key == "LENGTH" || key == "FORCE" || key == "ANGLE" || key == "MASS" || key == "TIME") {
      check_si_unit(key, unquote(value), where);
    } else {
      file.other_entries.push_back({section.empty() ? std::string("MDI_HEADER") : section, key, std::string(value)});
    }
  }
  if (file.property_file_format.empty()) file.property_file_format = "PAC2002";
  if (file.tyre_side.empty()) file.tyre_side = "LEFT";
  return file;
}

TirFile read_tir_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw TirFileError(fmt::format("{}: cannot open the .tir file", file.string()));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_tir(buffer.str(), file.string());
}

}  // namespace tirefem
