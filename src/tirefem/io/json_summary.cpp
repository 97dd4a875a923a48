#include "tirefem/io/json_summary.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace tirefem {
namespace {

void check_finite(const std::filesystem::path& file, const toml::node& node, const std::string& key_path) {
  if (const auto* value = node.as_floating_point()) {
    if (!std::isfinite(value->get()))
      throw std::invalid_argument(fmt::format("JSON '{}': key '{}' is {}; only finite numbers can be written",
                                              file.string(), key_path, value->get()));
  } else if (const auto* table = node.as_table()) {
    for (const auto& [key, child] : *table)
      check_finite(file, child,
                   key_path.empty() ? std::string(key.str()) : fmt::format("{}.{}", key_path, key.str()));
  } else if (const auto* array = node.as_array()) {
    for (std::size_t i = 0; i < array->size(); ++i)
      check_finite(file, *array->get(i), fmt::format("{}[{}]", key_path, i));
  }
}

}  // namespace

void write_json(const std::filesystem::path& file, const toml::table& table) {
  check_finite(file, table, "");
  std::ostringstream text;  // formatted completely before the file is opened
  text << toml::json_formatter{table} << '\n';
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out)
    throw std::runtime_error(
        fmt::format("cannot open JSON file '{}' for writing: {}", file.string(), std::strerror(errno)));
  out << text.str();
  out.close();
  if (!out) throw std::runtime_error(fmt::format("error while writing JSON file '{}'", file.string()));
}

}  // namespace tirefem
