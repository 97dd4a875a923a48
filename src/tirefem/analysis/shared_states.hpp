#pragma once
// States shared by the studies of one run: one tyre mesh and one nonlinear inflation per mesh setting
// (solved once per tyre and mesh, not once per study), and the completed static footprints that rolling
// studies at the same load start from. Both may be read by studies running at the same time.
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "tirefem/analysis/footprint.hpp"

namespace tirefem {

class InflatedTyres {
 public:
  // `solved(mesh, seconds)` is told of each inflation this object solves.
  InflatedTyres(const Case& c, const ProgressSink& progress,
                std::function<void(const MeshSettings&, double)> solved = {})
      : case_(c), progress_(progress), solved_(std::move(solved)) {}
  const TyreMesh& mesh(const MeshSettings& m);
  // The nonlinear inflated state of that mesh at the case's pressure (throws when it does not converge).
  const InflationResult& inflated(const MeshSettings& m);
  void adopt(const MeshSettings& m, const InflationResult& r);

 private:
  struct Entry {
    std::unique_ptr<TyreMesh> mesh;  // stable address: forms refer to it
    std::optional<InflationResult> inflated;
  };
  Entry& entry(const MeshSettings& m);
  const Case& case_;
  ProgressSink progress_;
  std::function<void(const MeshSettings&, double)> solved_;
  std::recursive_mutex mutex_;
  std::map<std::tuple<int, int, bool, double, int, int>, Entry> entries_;
};

// Completed static footprints by mesh, support and target load: a rolling study at the load and on the
// support of an earlier footprint (a [[footprint]] study on the case's mesh, or another rolling study)
// starts from it instead of solving it again.
class SharedFootprints {
 public:
  // What identifies a footprint: studies with the same key share it (and so must run one after another).
  static std::string key(const MeshSettings& m, const SupportDescription& s, double load, double tolerance);
  const StaticContactResult* find(const std::string& key) const;
  void keep(const std::string& key, const StaticContactResult& r);

 private:
  mutable std::mutex mutex_;
  std::map<std::string, StaticContactResult> entries_;  // node-based: found pointers stay valid
};

// The two states of a load curve (its path kept) on either side of `load`, the last below and the first
// at or above it, carried from the curve's mesh onto `mesh` (interpolated_onto, or mirrored_onto from a
// half model onto its full model; their Qz the curve's): where a footprint on `mesh` at that load starts
// from (run_footprint's `nearby`). Empty when the curve does not reach the load or the states cannot be
// carried (the meshes differ in meridional stations, or in kind other than half onto its own full).
std::vector<PathState> load_curve_states_near(const StaticContactResult& curve, const TyreMesh& curve_mesh,
                                              const TyreMesh& mesh, double load);

}  // namespace tirefem
