// ResultsFolder: results appear only on commit, replace older ones, and vanish when the run fails.
#include <fstream>
#include <string>

#include <fcntl.h>
#include <linux/fs.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
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


// Makes a folder unwritable while it lives: its owner's write permission removed, or for root, whom
// permissions do not stop, its immutable attribute set (as `chattr +i` does; `made()` is false where the
// file system or the process's capabilities do not allow it).
class UnwritableFolder {
 public:
  explicit UnwritableFolder(fs::path dir) : dir_(std::move(dir)), root_(geteuid() == 0) {
    if (root_) {
      made_ = set_immutable(true);
    } else {
      fs::permissions(dir_, fs::perms::owner_write, fs::perm_options::remove);
      made_ = true;
    }
  }
  ~UnwritableFolder() {
    if (!made_) return;
    if (root_) set_immutable(false);
    else fs::permissions(dir_, fs::perms::owner_write, fs::perm_options::add);
  }
  UnwritableFolder(const UnwritableFolder&) = delete;
  UnwritableFolder& operator=(const UnwritableFolder&) = delete;
  bool made() const { return made_; }

 private:
  bool set_immutable(bool on) const {
    const int fd = open(dir_.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return false;
    int flags = 0;
    bool ok = ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0;
    if (ok) {
      flags = on ? (flags | FS_IMMUTABLE_FL) : (flags & ~FS_IMMUTABLE_FL);
      ok = ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0;
    }
    close(fd);
    return ok;
  }
  fs::path dir_;
  bool root_ = false;
  bool made_ = false;
};

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

// A results folder of an earlier run, with the marker tirefem writes.
fs::path earlier_results(const fs::path& dir) {
  {
    ResultsFolder folder(dir);
    write_file(folder.path("summary.json"), "old\n");
    write_file(folder.path("stale.csv"), "old\n");
    write_file(folder.path("old_subdir/a.vtu"), "old\n");
    folder.commit();
  }
  return dir;
}

TEST(IoResultsFolder, CommitReplacesWhatTheLastRunWrote) {
  ScratchDir scratch;
  const fs::path final_dir = earlier_results(scratch.path / "results");
  {
    ResultsFolder folder(final_dir / "");  // trailing separator means the same folder
    write_file(folder.path("summary.json"), "new\n");
    EXPECT_EQ(read_file(final_dir / "summary.json"), "old\n") << "old results must survive until commit";
    EXPECT_EQ(folder.commit(), fs::absolute(final_dir).lexically_normal());
  }
  EXPECT_EQ(read_file(final_dir / "summary.json"), "new\n");
  EXPECT_FALSE(fs::exists(final_dir / "stale.csv"));
  EXPECT_FALSE(fs::exists(final_dir / "old_subdir"));
  EXPECT_EQ(entries_in(scratch.path), 1);
}

TEST(IoResultsFolder, KeepsWhatTheUserAddedToAResultsFolder) {
  ScratchDir scratch;
  const fs::path final_dir = earlier_results(scratch.path / "results");
  write_file(final_dir / "notes.txt", "mine\n");
  fs::create_directories(final_dir / "my_plots");
  write_file(final_dir / "my_plots" / "p.txt", "mine\n");
  {
    ResultsFolder folder(final_dir);
    write_file(folder.path("summary.json"), "new\n");
    folder.commit();
  }
  EXPECT_EQ(read_file(final_dir / "summary.json"), "new\n");
  EXPECT_FALSE(fs::exists(final_dir / "stale.csv")) << "an entry the last run wrote is replaced";
  EXPECT_EQ(read_file(final_dir / "notes.txt"), "mine\n");
  EXPECT_EQ(read_file(final_dir / "my_plots" / "p.txt"), "mine\n");
  EXPECT_EQ(entries_in(scratch.path), 1) << "temporary or set-aside folders left behind";
}

TEST(IoResultsFolder, RefusesAFolderItDidNotWriteUnlessForced) {
  ScratchDir scratch;
  const fs::path user = scratch.path / "user";
  fs::create_directories(user / "sub");
  write_file(user / "notes.txt", "mine\n");
  write_file(user / "summary.json", "mine\n");
  EXPECT_THROW(ResultsFolder{user}, ResultsFolderError);
  EXPECT_EQ(entries_in(scratch.path), 1) << "nothing created beside a refused folder";
  {
    ResultsFolder folder(user, {.force = true});
    write_file(folder.path("summary.json"), "new\n");
    write_file(folder.path("load_curve.csv"), "new\n");
    // summary.json is the user's: the results go to a free sibling instead of overwriting it.
    EXPECT_EQ(folder.commit(), fs::absolute(scratch.path / "user-2"));
  }
  EXPECT_EQ(read_file(user / "summary.json"), "mine\n");
  EXPECT_EQ(read_file(user / "notes.txt"), "mine\n");
  EXPECT_TRUE(fs::exists(user / "sub"));
  EXPECT_EQ(read_file(scratch.path / "user-2" / "summary.json"), "new\n");
  fs::remove(user / "summary.json");
  {
    ResultsFolder folder(user, {.force = true});  // no clash: added beside the user's files
    write_file(folder.path("summary.json"), "new\n");
    EXPECT_EQ(folder.commit(), fs::absolute(user));
  }
  EXPECT_EQ(read_file(user / "summary.json"), "new\n");
  EXPECT_EQ(read_file(user / "notes.txt"), "mine\n");
  EXPECT_TRUE(fs::exists(user / "sub"));
}

TEST(IoResultsFolder, AcceptsAnEmptyFolder) {
  ScratchDir scratch;
  fs::create_directories(scratch.path / "empty");
  ResultsFolder folder(scratch.path / "empty");
  write_file(folder.path("summary.json"), "new\n");
  folder.commit();
  EXPECT_EQ(read_file(scratch.path / "empty" / "summary.json"), "new\n");
}

TEST(IoResultsFolder, RefusesFilesTheWorkingFolderAndTheCaseFolder) {
  ScratchDir scratch;
  write_file(scratch.path / "case.toml", "x\n");
  EXPECT_THROW(ResultsFolder{scratch.path / "case.toml"}, ResultsFolderError);
  EXPECT_EQ(read_file(scratch.path / "case.toml"), "x\n");
  EXPECT_THROW(ResultsFolder(scratch.path, {.force = true, .case_file = scratch.path / "case.toml"}),
               ResultsFolderError);
  EXPECT_THROW(ResultsFolder("/"), std::runtime_error);
  const fs::path cwd = fs::current_path();
  fs::create_directories(scratch.path / "work");
  fs::current_path(scratch.path / "work");
  EXPECT_THROW(ResultsFolder("."), ResultsFolderError);
  EXPECT_THROW(ResultsFolder(".."), ResultsFolderError);
  EXPECT_THROW(ResultsFolder("./", {.force = true}), ResultsFolderError);
  fs::current_path(cwd);
  EXPECT_EQ(entries_in(scratch.path), 2);
}

TEST(IoResultsFolder, AForeignMarkerFileIsNotTakenForOurs) {
  ScratchDir scratch;
  fs::create_directories(scratch.path / "d");
  write_file(scratch.path / "d" / std::string(kResultsMarker), "my own file\n");
  EXPECT_THROW(ResultsFolder{scratch.path / "d"}, ResultsFolderError);
  EXPECT_THROW(ResultsFolder(scratch.path / "d", {.force = true}), ResultsFolderError);
  EXPECT_EQ(read_file(scratch.path / "d" / std::string(kResultsMarker)), "my own file\n");
}

TEST(IoResultsFolder, RefusesAReadOnlyFolder) {
  ScratchDir scratch;
  const fs::path dir = earlier_results(scratch.path / "results");
  {
    const UnwritableFolder unwritable(dir);
    if (!unwritable.made()) GTEST_SKIP() << "root here cannot set a folder's immutable attribute";
    EXPECT_THROW(ResultsFolder{dir}, ResultsFolderError);
  }
  EXPECT_EQ(read_file(dir / "summary.json"), "old\n");
}

TEST(IoResultsFolder, StoppedShortRunGoesBesideTheLastResults) {
  ScratchDir scratch;
  const fs::path final_dir = earlier_results(scratch.path / "results");
  {
    ResultsFolder folder(final_dir);
    write_file(folder.path("summary.json"), "partial\n");
    EXPECT_EQ(folder.commit("-incomplete"), fs::absolute(scratch.path / "results-incomplete"));
  }
  EXPECT_EQ(read_file(final_dir / "summary.json"), "old\n");
  EXPECT_EQ(read_file(scratch.path / "results-incomplete" / "summary.json"), "partial\n");
}

TEST(IoResultsFolder, LaterRunRemovesTheTemporaryFolderOfAKilledOne) {
  ScratchDir scratch;
  const fs::path final_dir = scratch.path / "results";
  // A temporary folder as a run killed by SIGKILL leaves it: its process (a child that has exited) is gone.
  const pid_t child = fork();
  if (child == 0) _exit(0);
  int status = 0;
  waitpid(child, &status, 0);
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  const fs::path stale = scratch.path / ".results.tmp-0badc0de";
  fs::create_directories(stale / "plots");
  write_file(stale / std::string(kResultsMarker),
             "tirefem results folder\npid " + std::to_string(child) + " host " + host + "\n");
  const fs::path alive = scratch.path / ".results.tmp-00000001";  // a run still writing (this process)
  fs::create_directories(alive);
  write_file(alive / std::string(kResultsMarker),
             "tirefem results folder\npid " + std::to_string(getpid()) + " host " + host + "\n");
  const fs::path not_ours = scratch.path / ".results.tmp-00000002";
  fs::create_directories(not_ours);
  write_file(not_ours / "x", "x\n");
  {
    ResultsFolder folder(final_dir);
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(alive));
    EXPECT_TRUE(fs::exists(not_ours));
  }
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
