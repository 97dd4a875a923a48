// CSV writer: comments, header, round-trip precision, and errors that name the file.
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "scratch_dir.hpp"
#include "tirefem/io/csv_writer.hpp"

namespace tirefem {
namespace {
namespace fs = std::filesystem;

// A scratch folder of this file's own.
struct ScratchDir : test::ScratchDir {
  ScratchDir() : test::ScratchDir("io_csv") {}
};
using test::read_file;

TEST(IoCsvWriter, WritesCommentsHeaderAndRows) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "load.csv";
  CsvTable table;
  table.comments = {"load characteristic", "p = 0.2 MPa\nplane road"};
  table.columns = {"deflection_mm", "Qz_N"};
  table.rows = {{0.0, 0.0}, {1.5, 1234.5}, {0.1, 1e-20}, {-3.0, 2e20}};
  write_csv(file, table);
  EXPECT_EQ(read_file(file),
            "# load characteristic\n"
            "# p = 0.2 MPa\n"
            "# plane road\n"
            "deflection_mm,Qz_N\n"
            "0,0\n"
            "1.5,1234.5\n"
            "0.1,1e-20\n"
            "-3,2e+20\n");
}

TEST(IoCsvWriter, ValuesReadBackExactly) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "precision.csv";
  const double values[] = {1.0 / 3.0, 2.0 / 3.0 * 1e-7, 123456.789012345678,
                           std::numeric_limits<double>::min(), -std::numeric_limits<double>::max()};
  CsvTable table{{"v"}, {}, {}};
  for (double v : values) table.rows.push_back({v});
  write_csv(file, table);
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "v");
  for (double v : values) {
    ASSERT_TRUE(std::getline(in, line));
    EXPECT_EQ(std::strtod(line.c_str(), nullptr), v) << line;
  }
}

TEST(IoCsvWriter, NonFiniteValuesAreWrittenAsNanAndInf) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "nan.csv";
  CsvTable table{{"a_mm", "b_N", "c_N"},
                 {{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity()}},
                 {}};
  write_csv(file, table);
  EXPECT_EQ(read_file(file), "a_mm,b_N,c_N\nnan,inf,-inf\n");
}

TEST(IoCsvWriter, RowWithWrongLengthNamesFileAndRowAndWritesNothing) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "bad.csv";
  CsvTable table{{"s_mm", "Qz_N"}, {{1, 2}, {3}}, {}};
  try {
    write_csv(file, table);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("bad.csv"), std::string::npos) << message;
    EXPECT_NE(message.find("row 1 has 1 values, expected 2"), std::string::npos) << message;
  }
  EXPECT_FALSE(fs::exists(file));
}

TEST(IoCsvWriter, RejectsBadColumnNames) {
  ScratchDir scratch;
  EXPECT_THROW(write_csv(scratch.path / "a.csv", CsvTable{{"a,b"}, {}, {}}), std::invalid_argument);
  EXPECT_THROW(write_csv(scratch.path / "a.csv", CsvTable{{""}, {}, {}}), std::invalid_argument);
  EXPECT_THROW(write_csv(scratch.path / "a.csv", CsvTable{{}, {}, {}}), std::invalid_argument);
}

TEST(IoCsvWriter, UnwritableFileNamesTheFile) {
  ScratchDir scratch;
  const fs::path file = scratch.path / "no_such_folder" / "x.csv";
  try {
    write_csv(file, CsvTable{{"x"}, {{1}}, {}});
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tirefem
