// ResultsFolder: results appear only on commit, replace older ones, and vanish when the run fails.
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "scratch_dir.hpp"
#include "tirefem/io/results_folder.hpp"

namespace tirefem {
namespace {
namespace fs = std::filesystem;

// A scratch folder of this file's own.
struct ScratchDir : test::ScratchDir {
  ScratchDir() : test::ScratchDir("io_results_folder") {}
};
using test::read_file;

void write_file(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }


int entries_in(const fs::path& dir) {
  return static_cast<int>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(IoResultsFolder, NotCommittedLeavesNothing) {
  ScratchDir scratch;
  const fs::path final_dir = scratch.path / "results";
  {
    ResultsFolder folder(final_dir);
    write_file(folder.path("a.csv"), "x\n1\n");
    EXPECT_TRUE(fs::exists(folder.path("a.csv")));
    EXPECT_EQ(folder.path("a.csv").parent_path().parent_path(),
              fs::absolute(scratch.path).lexically_normal());
    EXPECT_FALSE(fs::exists(final_dir));
  }
  EXPECT_FALSE(fs::exists(final_dir));
  EXPECT_EQ(entries_in(scratch.path), 0) << "the temporary folder was not removed";
}

TEST(IoResultsFolder, FailedRunLeavesNothing) {
  ScratchDir scratch;
  const fs::path final_dir = scratch.path / "results";
  try {
    ResultsFolder folder(final_dir);
    write_file(folder.path("half.csv"), "x\n");
    throw std::runtime_error("solver diverged");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(entries_in(scratch.path), 0);
}

TEST(IoResultsFolder, CommitMovesFilesIntoPlace) {
  ScratchDir scratch;
  const fs::path final_dir = scratch.path / "sub" / "results";  // parent created on demand
  {
    ResultsFolder folder(final_dir);
    write_file(folder.path("summary.json"), "{}\n");
    write_file(folder.path("vtu/step_01.vtu"), "<VTKFile/>\n");  // nested folders created on demand
    folder.commit();
    EXPECT_TRUE(folder.committed());
    EXPECT_EQ(folder.path("summary.json"), fs::absolute(final_dir) / "summary.json");
  }
  EXPECT_EQ(read_file(final_dir / "summary.json"), "{}\n");
  EXPECT_EQ(read_file(final_dir / "vtu" / "step_01.vtu"), "<VTKFile/>\n");
  EXPECT_EQ(entries_in(scratch.path / "sub"), 1) << "temporary or old folders left behind";
}

TEST(IoResultsFolder, CommitReplacesOldResults) {
  ScratchDir scratch;
  const fs::path final_dir = scratch.path / "results";
  fs::create_directories(final_dir / "old_subdir");
  write_file(final_dir / "stale.csv", "old\n");
  write_file(final_dir / "summary.json", "old\n");
  {
    ResultsFolder folder(final_dir / "");  // trailing separator means the same folder
    write_file(folder.path("summary.json"), "new\n");
    EXPECT_EQ(read_file(final_dir / "summary.json"), "old\n") << "old results must survive until commit";
    folder.commit();
  }
  EXPECT_EQ(read_file(final_dir / "summary.json"), "new\n");
  EXPECT_FALSE(fs::exists(final_dir / "stale.csv"));
  EXPECT_FALSE(fs::exists(final_dir / "old_subdir"));
  EXPECT_EQ(entries_in(scratch.path), 1);
}

TEST(IoResultsFolder, RejectsNamesOutsideTheFolder) {
  ScratchDir scratch;
  ResultsFolder folder(scratch.path / "results");
  EXPECT_THROW(folder.path("../escape.csv"), std::invalid_argument);
  EXPECT_THROW(folder.path("a/../../escape.csv"), std::invalid_argument);
  EXPECT_THROW(folder.path("/etc/passwd"), std::invalid_argument);
  EXPECT_THROW(folder.path(""), std::invalid_argument);
  folder.commit();
  EXPECT_THROW(folder.commit(), std::logic_error);
}

TEST(IoResultsFolder, MovedFromFolderDoesNotDeleteTheResults) {
  ScratchDir scratch;
  const fs::path final_dir = scratch.path / "results";
  auto make = [&] {
    ResultsFolder folder(final_dir);
    write_file(folder.path("a.txt"), "a\n");
    return folder;
  };
  ResultsFolder folder = make();
  EXPECT_TRUE(fs::exists(folder.path("a.txt")));
  folder.commit();
  EXPECT_EQ(read_file(final_dir / "a.txt"), "a\n");
}

}  // namespace
}  // namespace tirefem
