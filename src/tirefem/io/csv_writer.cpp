#include "tirefem/io/csv_writer.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

namespace tirefem {
namespace {

void check_table(const std::filesystem::path& file, const CsvTable& table) {
  if (table.columns.empty())
    throw std::invalid_argument(fmt::format("CSV '{}': the table has no columns", file.string()));
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const std::string& name = table.columns[c];
    if (name.empty() || name.find_first_of(",\"\r\n") != std::string::npos)
      throw std::invalid_argument(fmt::format(
          "CSV '{}': column {} name '{}' must be non-empty and contain no comma, quote or line break",
          file.string(), c, name));
  }
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    if (table.rows[r].size() != table.columns.size())
      throw std::invalid_argument(fmt::format("CSV '{}': row {} has {} values, expected {} (columns: {})",
                                              file.string(), r, table.rows[r].size(), table.columns.size(),
                                              fmt::join(table.columns, ", ")));
}

void write_text_file(const std::filesystem::path& file, std::string_view text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out)
    throw std::runtime_error(
        fmt::format("cannot open CSV file '{}' for writing: {}", file.string(), std::strerror(errno)));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error(fmt::format("error while writing CSV file '{}'", file.string()));
}

}  // namespace

void write_csv(const std::filesystem::path& file, const CsvTable& table) {
  check_table(file, table);
  fmt::memory_buffer text;
  for (const std::string& comment : table.comments) {
    std::size_t start = 0;
    while (true) {
      const std::size_t end = comment.find('\n', start);
      fmt::format_to(std::back_inserter(text), "# {}\n",
                     std::string_view(comment).substr(start, end == std::string::npos ? end : end - start));
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  fmt::format_to(std::back_inserter(text), "{}\n", fmt::join(table.columns, ","));
  for (const std::vector<double>& row : table.rows)
    fmt::format_to(std::back_inserter(text), "{}\n", fmt::join(row, ","));
  write_text_file(file, std::string_view(text.data(), text.size()));
}

}  // namespace tirefem
