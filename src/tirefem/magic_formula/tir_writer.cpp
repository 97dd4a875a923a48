#include "tirefem/magic_formula/tir_writer.hpp"

#include <fmt/format.h>

#include <fstream>
#include <set>
#include <stdexcept>
#include <string_view>

namespace tirefem {
namespace {

void append_rule(std::string& out, std::string_view name) {
  out += fmt::format("${:->69}\n", name);
}

void append_other_entries(std::string& out, const TirFile& file, std::string_view section) {
  for (const TirEntry& entry : file.other_entries)
    if (entry.section == section) out += fmt::format("{:<24} = {}\n", entry.key, entry.value);
}

void append_coefficient(std::string& out, const TirFile& file, const CoefficientInfo& info) {
  const double value = file.coefficients.*(info.member);
  const auto note = file.notes.find(std::string(info.key));
  if (info.optional && value == info.neutral && note == file.notes.end()) return;
  // fmt's "{}" for a double is the shortest text that parses back to the same value.
  std::string line = fmt::format("{:<24} = {:<22} ${}", info.key, fmt::format("{}", value), info.description);
  if (note != file.notes.end()) line += fmt::format(" ({})", note->second);
  out += line;
  out += '\n';
}

}  // namespace

std::string format_tir(const TirFile& file) {
  std::string out;
  out += "[MDI_HEADER]\n";
  out += fmt::format("{:<24} = '{}'\n", "FILE_TYPE", file.file_type);
  out += fmt::format("{:<24} = {}\n", "FILE_VERSION", fmt::format("{}", file.coefficients.FILE_VERSION));
  out += fmt::format("{:<24} = '{}'\n", "FILE_FORMAT", file.file_format);
  out += fmt::format("! : TIRE_VERSION : {}\n", file.property_file_format);
  for (const std::string& comment : file.header_comments) out += fmt::format("! : COMMENT : {}\n", comment);
  append_other_entries(out, file, "MDI_HEADER");

  append_rule(out, "units");
  out += "[UNITS]\n";
  out += "LENGTH                   = 'meter'\nFORCE                    = 'newton'\nANGLE                    = 'radian'\n";
  out += "MASS                     = 'kg'\nTIME                     = 'second'\n";
  append_other_entries(out, file, "UNITS");

  std::set<std::string_view> written{"MDI_HEADER", "UNITS"};
  std::string_view section;
  for (const CoefficientInfo& info : coefficient_table()) {
    if (info.section == "MDI_HEADER") continue;
    if (info.section != section) {
      if (!section.empty()) append_other_entries(out, file, section);
      section = info.section;
      written.insert(section);
      append_rule(out, section);
      out += fmt::format("[{}]\n", section);
      if (section == "MODEL") {
        out += fmt::format("{:<24} = '{}'\n", "PROPERTY_FILE_FORMAT", file.property_file_format);
        out += fmt::format("{:<24} = '{}'\n", "TYRESIDE", file.tyre_side);
      }
    }
    append_coefficient(out, file, info);
  }
  append_other_entries(out, file, section);

  // Sections the table does not know (e.g. [SHAPE] keys), in their first order of appearance.
  std::set<std::string> extra_written;
  for (const TirEntry& entry : file.other_entries) {
    if (written.contains(entry.section) || extra_written.contains(entry.section)) continue;
    extra_written.insert(entry.section);
    append_rule(out, entry.section);
    out += fmt::format("[{}]\n", entry.section);
    append_other_entries(out, file, entry.section);
  }
  return out;
}

void write_tir_file(const std::filesystem::path& path, const TirFile& file) {
  const std::string text = format_tir(file);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(fmt::format("{}: cannot open the .tir file for writing", path.string()));
  out << text;
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write the .tir file", path.string()));
}

}  // namespace tirefem
