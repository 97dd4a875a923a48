#pragma once
// Wall time per phase of a run (run_case): printed at the end and kept in summary.json.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "tirefem/solver/newton.hpp"

namespace tirefem {

// A shared inflation is a phase of its own, taken out of the study during which it was solved.
class PhaseTimes {
 public:
  using Clock = std::chrono::steady_clock;
  void begin(std::string name) {
    name_ = std::move(name);
    start_ = Clock::now();
    nested_ = 0.0;
  }
  void end() { phases_.emplace_back(name_, seconds(start_) - nested_); }
  void add(std::string name, double s) { phases_.emplace_back(std::move(name), s); }
  void nested(std::string name, double s) {
    phases_.emplace_back(std::move(name), s);
    nested_ += s;
  }
  void report(const ProgressSink& progress, double total) const {
    if (!progress) return;
    progress("time per phase:");
    for (const auto& [name, s] : phases_) progress(fmt::format("  {:<40} {:9.2f} s", name, s));
    progress(fmt::format("  {:<40} {:9.2f} s", "total", total));
  }
  toml::array table() const {
    toml::array a;
    for (const auto& [name, s] : phases_) a.push_back(toml::table{{"phase", name}, {"time_s", s}});
    return a;
  }

 private:
  static double seconds(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
  std::string name_;
  Clock::time_point start_;
  double nested_ = 0.0;
  std::vector<std::pair<std::string, double>> phases_;
};

}  // namespace tirefem
