#pragma once
// Comma-separated tables of numbers, one header line of column names (with units, e.g. "s_mm", "Qz_N"),
// optionally preceded by '# ' comment lines (read them with pandas.read_csv(comment='#') or
// numpy.genfromtxt(names=True)).
#include <filesystem>
#include <string>
#include <vector>

namespace tirefem {

struct CsvTable {
  std::vector<std::string> columns;       // names include units, e.g. "s_mm"
  std::vector<std::vector<double>> rows;  // each row has columns.size() values
  std::vector<std::string> comments;      // written first as '# ' lines; a '\n' starts a new comment line
};

// Values are written in the shortest form that reads back to the identical double ("0.1", "3", "1e-20");
// NaN and infinities as "nan", "inf", "-inf". Checks before writing anything that the column names are
// non-empty and free of ',', '"' and line breaks and that every row has one value per column
// (std::invalid_argument naming the file and the row); throws std::runtime_error naming the file when it
// cannot be written.
void write_csv(const std::filesystem::path& file, const CsvTable& table);

}  // namespace tirefem
