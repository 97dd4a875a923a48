#pragma once
// The results folder belongs to the user: tirefem deletes or replaces only what it wrote itself.
//
// Everything is written into a temporary hidden sibling `.<name>.tmp-<hex>` and moved into place by
// commit(). A results folder carries a marker file (kResultsMarker) listing the entries tirefem put there;
// a later run replaces exactly those and leaves anything the user added. A folder without the marker that
// is not empty is refused (unless `force`, which adds the results beside its files without touching them),
// as are a file, the current folder or one of its parents, a folder holding the case file, and a folder
// that cannot be written: all before anything is solved. A failed or interrupted run (the object destroyed
// uncommitted) removes its temporary folder; temporary folders left by a killed run are removed by the
// next run into the same folder, once their process is gone.
#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace tirefem {

inline constexpr std::string_view kResultsMarker = ".tirefem-results";

// A results folder that cannot be used; the message names it and says what to do instead.
class ResultsFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ResultsFolderPolicy {
  bool force = false;               // accept a non-empty folder tirefem did not write (adds beside)
  std::filesystem::path case_file;  // the folder holding it (or a parent of it) is refused
};

class ResultsFolder {
 public:
  // Checks `final_dir` against the policy (ResultsFolderError), removes stale temporary folders of
  // earlier killed runs, and creates the temporary folder (creating `final_dir`'s parent if needed).
  explicit ResultsFolder(std::filesystem::path final_dir, const ResultsFolderPolicy& policy = {});
  // Not committed: removes the temporary folder and everything in it (never throws).
  ~ResultsFolder();

  ResultsFolder(const ResultsFolder&) = delete;
  ResultsFolder& operator=(const ResultsFolder&) = delete;
  ResultsFolder(ResultsFolder&& other) noexcept;
  ResultsFolder& operator=(ResultsFolder&&) = delete;

  // Where to write `file_name` (a relative name such as "summary.json" or "vtu/step_01.vtu"): inside the
  // temporary folder before commit(), inside the committed folder after. Creates intermediate folders of
  // a nested name. Throws std::invalid_argument for an absolute name or one that climbs out with "..".
  std::filesystem::path path(std::string_view file_name) const;

  // Moves the results into `final_dir` + `suffix` (e.g. "-incomplete" for a run that stopped short, so
  // that the last complete results stay as they were). The entries a previous run wrote there are
  // replaced; nothing else in the folder is touched. Should a result's name collide with a file the user
  // put there, the results go to the first free `<folder>-2`, `-3`, … instead. Returns the folder used.
  // Throws std::runtime_error naming the folders if moving fails (the old results are then restored).
  std::filesystem::path commit(std::string_view suffix = {});

  bool committed() const { return committed_; }
  const std::filesystem::path& final_dir() const { return final_dir_; }
  const std::filesystem::path& committed_dir() const { return committed_dir_; }
  const std::filesystem::path& temp_dir() const { return temp_dir_; }

 private:
  std::filesystem::path final_dir_;
  std::filesystem::path temp_dir_;
  std::filesystem::path committed_dir_;
  bool force_ = false;
  bool committed_ = false;
};

}  // namespace tirefem
