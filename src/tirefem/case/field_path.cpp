#include "tirefem/case/field_path.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <vector>

namespace tirefem::case_reading {

std::string join(const std::string& path, std::string_view key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  const std::string k = bare ? std::string(key) : fmt::format("\"{}\"", key);
  return path.empty() ? k : path + "." + k;
}

std::string index(const std::string& path, std::size_t i) { return fmt::format("{}[{}]", path, i); }

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string_view closest_key(std::string_view key, std::initializer_list<std::string_view> candidates) {
  std::string_view close;
  std::size_t best = std::string_view::npos;
  for (std::string_view a : candidates) {
    const std::size_t d = edit_distance(a, key);
    if (d < a.size() && d <= std::max<std::size_t>(2, a.size() / 4) && d < best) close = a, best = d;
  }
  return close;
}

}  // namespace tirefem::case_reading
