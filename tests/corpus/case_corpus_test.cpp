// The corpus of malformed case files (tests/corpus/bad, written by tests/corpus/make_bad_cases.py): each
// must be refused by read_case with a CaseError (no other exception, no crash) that names the file and
// the field its first line announces (`# expect: FIELD`). Nothing is solved.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tirefem/case/case_reader.hpp"

namespace tirefem {
namespace {

const std::filesystem::path kCorpus = std::filesystem::path(TIREFEM_SOURCE_DIR) / "tests/corpus/bad";

std::vector<std::string> corpus_files() {
  std::vector<std::string> files;
  if (std::filesystem::is_directory(kCorpus))
    for (const auto& e : std::filesystem::directory_iterator(kCorpus))
      if (e.path().extension() == ".toml") files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

// The field named on the first line, "# expect: FIELD".
std::string expected_field(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  const std::string tag = "# expect: ";
  return line.rfind(tag, 0) == 0 ? line.substr(tag.size()) : std::string();
}

TEST(CaseCorpus, HasAtLeastSixtyFiles) { EXPECT_GE(corpus_files().size(), 60u); }

class CaseCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(CaseCorpus, RefusedWithTheFieldNamed) {
  const std::filesystem::path file = kCorpus / GetParam();
  const std::string field = expected_field(file);
  ASSERT_FALSE(field.empty()) << file << ": the first line must be '# expect: FIELD'";
  try {
    read_case(file);
    FAIL() << file << ": accepted";
  } catch (const CaseError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.string() + ":", 0), 0u) << message;  // starts with the file
    EXPECT_NE(message.find(": " + field), std::string::npos) << "expected the field " << field << " in: " << message;
  } catch (const std::exception& e) {
    FAIL() << file << ": not a CaseError: " << e.what();
  }
}

// Test names: the file name without its extension, '-' replaced (gtest allows [A-Za-z0-9_]).
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = std::filesystem::path(info.param).stem().string();
  std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Bad, CaseCorpus, ::testing::ValuesIn(corpus_files()), test_name);

}  // namespace
}  // namespace tirefem
