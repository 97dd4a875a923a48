#pragma once
// A results folder that appears only when a run finishes: everything is written into a temporary sibling
// folder, and commit() moves it into place. A failed run (exception, early return) leaves the previous
// results untouched and no half-written folder behind.
#include <filesystem>
#include <string_view>

namespace tirefem {

class ResultsFolder {
 public:
  // Creates the temporary folder `<parent>/.<name>.tmp-<random>` next to `final_dir` (creating `<parent>`
  // if needed). Throws std::runtime_error naming the folder if it cannot be created.
  explicit ResultsFolder(std::filesystem::path final_dir);
  // Not committed: removes the temporary folder and everything in it (never throws).
  ~ResultsFolder();

  ResultsFolder(const ResultsFolder&) = delete;
  ResultsFolder& operator=(const ResultsFolder&) = delete;
  ResultsFolder(ResultsFolder&& other) noexcept;
  ResultsFolder& operator=(ResultsFolder&&) = delete;

  // Where to write `file_name` (a relative name such as "summary.json" or "vtu/step_01.vtu"): inside the
  // temporary folder before commit(), inside the final folder after. Creates intermediate folders of a
  // nested name. Throws std::invalid_argument for an absolute name or one that climbs out with "..".
  std::filesystem::path path(std::string_view file_name) const;

  // Replaces `final_dir` by the temporary folder: an existing `final_dir` is first renamed aside, the
  // temporary folder renamed into place, then the old one deleted; if the second rename fails the old
  // results are restored. Throws std::runtime_error naming the folders on failure.
  void commit();

  bool committed() const { return committed_; }
  const std::filesystem::path& final_dir() const { return final_dir_; }
  const std::filesystem::path& temp_dir() const { return temp_dir_; }

 private:
  std::filesystem::path final_dir_;
  std::filesystem::path temp_dir_;
  bool committed_ = false;
};

}  // namespace tirefem
