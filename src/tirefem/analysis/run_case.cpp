#include "tirefem/analysis/run_case.hpp"

#include <atomic>
#include <chrono>
#include <mutex>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <omp.h>
#include <toml++/toml.h>

#include "tirefem/analysis/footprint.hpp"
#include "tirefem/analysis/inflation.hpp"
#include "tirefem/analysis/parallel_chains.hpp"
#include "tirefem/analysis/phase_times.hpp"
#include "tirefem/analysis/rolling.hpp"
#include "tirefem/analysis/shared_states.hpp"
#include "tirefem/analysis/study_reports.hpp"
#include "tirefem/analysis/study_runs.hpp"
#include "tirefem/analysis/tyre_test.hpp"
#include "tirefem/io/json_summary.hpp"
#include "tirefem/io/results_folder.hpp"
#include "tirefem/solver/blas_kernel.hpp"

namespace tirefem {
namespace {

toml::table blas_table() {
  const BlasKernel b = blas_kernel();
  return toml::table{{"library", b.library}, {"kernel", b.core}, {"kernel_forced", b.forced}};
}

void report(const ProgressSink& progress, const std::string& message) {
  if (progress) progress(message);
}

// The progress of studies that run at the same time: one line at a time, each prefixed by its study's
// name when more than one study runs; a stop (interrupt, or another study's worker failing) ends the study
// at its next progress line.
class StudyProgress {
 public:
  StudyProgress(const ProgressSink& progress, const std::atomic<bool>& stop, WorkerShare& share)
      : progress_(progress), stop_(stop), share_(share) {}
  // Called in the study's own thread between solver steps: where a stop takes effect, and where the last
  // study running takes the threads of the workers that ran out of studies (for its assembly).
  ProgressSink sink(const std::string& name, bool prefixed) {
    return [this, prefix = prefixed ? "[" + name + "] " : std::string()](const std::string& message) {
      if (stop_) throw RunInterrupted();
      share_.checkpoint();
      const std::lock_guard lock(mutex_);
      if (progress_) progress_(prefix + message);
    };
  }

 private:
  ProgressSink progress_;
  const std::atomic<bool>& stop_;
  WorkerShare& share_;
  std::mutex mutex_;
};
}  // namespace

RunOutcome run_case(const Case& c, const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  ResultsFolder folder(options.out_dir, {.force = options.force, .case_file = c.source});
  // Every solver reports progress between steps: that is where a requested stop takes effect.
  const ProgressSink progress = [&](const std::string& message) {
    if (options.stop_requested && !folder.committed() && options.stop_requested()) throw RunInterrupted();
    if (options.progress) options.progress(message);
  };
  PhaseTimes times;
  times.begin("mesh");
  InflatedTyres tyres(c, progress, [&](const MeshSettings& m, double s) {
    times.nested(fmt::format("inflation ({} x {} {}, shared)", m.circumferential_elements, m.meridional_elements,
                             m.half_model ? "half" : "full"),
                 s);
  });
  const TyreMesh& tm = tyres.mesh(c.mesh);
  const int equations = tm.mesh.dof_count() - static_cast<int>(tm.fixed_dofs.size());
  report(progress, fmt::format("{}: {} x {} {} model, {} elements, {} DOF ({} free)", c.title,
                                       c.mesh.circumferential_elements, c.mesh.meridional_elements,
                                       c.mesh.half_model ? "half" : "full", tm.mesh.element_count(),
                                       tm.mesh.dof_count(), equations));
  toml::table summary{{"tirefem_version", "0.1.0"},
                      {"title", c.title},
                      {"case_file", c.source.string()},
                      {"units", "mm, N, MPa"},
                      {"dof", tm.mesh.dof_count()},
                      {"free_dof", equations},
                      {"elements", tm.mesh.element_count()},
                      {"threads", omp_get_max_threads()},
                      {"blas", blas_table()},
                      {"mesh", toml::table{{"circumferential_elements", c.mesh.circumferential_elements},
                                           {"meridional_elements", c.mesh.meridional_elements},
                                           {"model", c.mesh.half_model ? "half" : "full"},
                                           {"faces", c.mesh.faces == MeshSettings::Faces::enhanced ? "enhanced"
                                                                                                  : "compatible"}}}};

  times.end();
  ReportWriter inflation_plots(folder, progress);
  if (c.inflation.enabled) {
    times.begin("inflation");
    const InflationResult r = run_inflation(tm, c.inflation, progress);
    if (!r.converged) throw std::runtime_error(r.failure);
    if (r.kinematics == Kinematics::nonlinear) tyres.adopt(c.mesh, r);  // the contact studies start here
    summary.insert("inflation", write_inflation(folder, inflation_plots, progress, tm, c, r));
    times.end();
  }

  // The inflated states every study starts from, one per mesh, solved first on all threads. One that does
  // not converge fails the studies on its mesh (they ask again and get the error).
  times.begin("inflations of the studies' meshes");
  for (const RollingStudy& s : c.rolling) {
    try {
      tyres.inflated(s.mesh.value_or(c.mesh));
    } catch (const std::runtime_error&) {
    }
  }
  for (const TyreTestStudy& s : c.tyre_tests) {
    try {
      // The half model first: the full model then starts from its mirror image, row by row.
      tyres.inflated(tyre_test_half_mesh(s.mesh.value_or(c.mesh)));
      tyres.inflated(s.mesh.value_or(c.mesh));
    } catch (const std::runtime_error&) {
    }
  }
  if (!c.load_curves.empty() || !c.footprints.empty()) {
    try {
      tyres.inflated(c.mesh);
    } catch (const std::runtime_error&) {
    }
  }
  times.end();

  // The studies, as chains of tasks: each study its own chain, except that a rolling study at the load,
  // support and mesh of an earlier footprint (or rolling study) runs after it, in its chain, and starts
  // from its footprint. Chains run side by side (parallel_chains.hpp).
  // A tyre test is a study per load and one for its load–deflection curve.
  const int rig_runs = tyre_test_run_count(c);
  const int study_count =
      static_cast<int>(c.load_curves.size() + c.footprints.size() + c.rolling.size()) + rig_runs;
  std::vector<StudyRun> runs(study_count);
  std::vector<TaskChain> chains;
  std::map<std::string, std::size_t> chain_of_footprint;
  SharedFootprints footprints;
  std::atomic<bool> stop{false};
  WorkerShare share(omp_get_max_threads());
  StudyProgress study_progress(progress, stop, share);
  bool prefixed = false;  // known once the chains are counted; the tasks read it when they run
  // A study that throws (e.g. its first contact state does not converge) stops short like one whose load
  // path ends early; the other studies go on.
  const auto task = [&](int k, std::string phase, std::function<void(const ProgressSink&)> solve) {
    runs[k].phase = std::move(phase);
    return [&, k, solve = std::move(solve)] {
      StudyRun& run = runs[k];
      const ProgressSink sink = study_progress.sink(run.phase, prefixed);
      const auto start = std::chrono::steady_clock::now();
      try {
        solve(sink);
      } catch (const RunInterrupted&) {
        throw;
      } catch (const std::exception& e) {
        run.error = fmt::format("{} failed: {}", run.phase, e.what());
        sink("warning: " + run.error);
      }
      run.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
  };
  // A footprint at a target load starts from the states of a load curve of the same problem (support,
  // theory, origin of δz), so it runs after that curve, in its chain.
  const auto problem_key = [&](const SupportDescription& support, bool linear, DeflectionOrigin origin) {
    return SharedFootprints::key(c.mesh, support, 0.0, 0.0) + (linear ? " linear " : " nonlinear ") +
           (origin == DeflectionOrigin::first_touch ? "first_touch" : "undeformed");
  };
  std::map<std::string, std::pair<std::size_t, int>> curve_of_problem;  // its chain and its study index
  std::vector<char> keep_path(c.load_curves.size(), 0);
  int k = 0;
  for (const LoadCurveStudy& s : c.load_curves) {
    chains.push_back({task(k, "load curve '" + s.name + "'", [&, k](const ProgressSink& sink) {
      runs[k].contact = run_load_curve(tm, c.tyre, c.inflation, c.contact, s, sink, &tyres.inflated(c.mesh),
                                       keep_path[k] != 0);
    })});
    curve_of_problem.try_emplace(problem_key(s.support, s.linear, s.deflection_from), chains.size() - 1, k);
    ++k;
  }
  for (const FootprintStudy& s : c.footprints) {
    // Shared only as a rolling study would solve it: nonlinear, at a target load, δz from the undeformed tyre.
    const bool shared = !s.linear && !s.deflection && s.deflection_from == DeflectionOrigin::undeformed;
    const std::string key = SharedFootprints::key(c.mesh, s.support, s.target_load, s.load_tolerance);
    const auto curve = s.deflection ? curve_of_problem.end()
                                    : curve_of_problem.find(problem_key(s.support, s.linear, s.deflection_from));
    const int along = curve == curve_of_problem.end() ? -1 : curve->second.second;
    auto solve = task(k, "footprint '" + s.name + "'", [&, k, shared, key, along](const ProgressSink& sink) {
      const StaticContactResult* path = along >= 0 && runs[along].contact ? &*runs[along].contact : nullptr;
      runs[k].contact = run_footprint(tm, c.tyre, c.inflation, c.contact, s, sink, &tyres.inflated(c.mesh), path);
      if (shared) footprints.keep(key, *runs[k].contact);
    });
    if (along >= 0) {
      keep_path[along] = 1;
      chains[curve->second.first].push_back(std::move(solve));
      if (shared) chain_of_footprint.try_emplace(key, curve->second.first);
    } else {
      chains.push_back({std::move(solve)});
      if (shared) chain_of_footprint.try_emplace(key, chains.size() - 1);
    }
    ++k;
  }
  for (const RollingStudy& s : c.rolling) {
    const MeshSettings settings = s.mesh.value_or(c.mesh);  // a copy: the task runs after this loop
    const std::string key = SharedFootprints::key(settings, s.support, s.target_load, s.load_tolerance);
    const auto it = chain_of_footprint.find(key);
    // A footprint of its own: from a load curve of the case's mesh on its support (nonlinear, δz from the
    // undeformed tyre), carried onto its mesh, when the meshes allow it; it then runs after that curve.
    const auto curve = it != chain_of_footprint.end()
                           ? curve_of_problem.end()
                           : curve_of_problem.find(problem_key(s.support, false, DeflectionOrigin::undeformed));
    const int along =
        curve != curve_of_problem.end() && interpolates_onto(tyres.mesh(c.mesh), tyres.mesh(settings))
            ? curve->second.second
            : -1;
    auto solve = task(k, "rolling '" + s.name + "'", [&, k, key, settings, along](const ProgressSink& sink) {
      const TyreMesh& mesh = tyres.mesh(settings);
      if (s.mesh)
        sink(fmt::format("rolling '{}' on its own mesh: {} x {}, {} elements", s.name, settings.circumferential_elements,
                         settings.meridional_elements, mesh.mesh.element_count()));
      std::vector<PathState> nearby;
      if (along >= 0 && runs[along].contact)
        nearby = load_curve_states_near(*runs[along].contact, tyres.mesh(c.mesh), mesh, s.target_load);
      runs[k].rolling = run_rolling(mesh, c.tyre, c.inflation, c.contact, s, sink, &tyres.inflated(settings),
                                    footprints.find(key), {}, nearby.empty() ? nullptr : &nearby);
      footprints.keep(key, runs[k].rolling->footprint);
    });
    if (it != chain_of_footprint.end()) {
      chains[it->second].push_back(std::move(solve));
    } else if (along >= 0) {
      keep_path[along] = 1;
      chains[curve->second.first].push_back(std::move(solve));
      chain_of_footprint.emplace(key, curve->second.first);
    } else {
      chains.push_back({std::move(solve)});
      chain_of_footprint.emplace(key, chains.size() - 1);
    }
    ++k;
  }
  // A tyre test: per load a task that solves the load's footprint and free rolling (RollingStart), where
  // both its series begin, each series a task after it; and the vertical curve. The plans are complete
  // before any task is made: the tasks refer to them.
  struct RigPlan {
    std::vector<RollingStudy> series;  // by load: longitudinal, lateral
    std::vector<std::optional<RollingStart>> starts;  // by load (the lateral series' footprint and free rolling)
    LoadCurveStudy vertical;
    MeshSettings mesh;
    TyreTestLongitudinalModel longitudinal = TyreTestLongitudinalModel::full;
    std::unique_ptr<TyreTestProgress> progress;
  };
  std::vector<RigPlan> rigs;
  for (const TyreTestStudy& s : c.tyre_tests) {
    RigPlan& r = rigs.emplace_back();
    r.mesh = s.mesh.value_or(c.mesh);
    try {
      r.longitudinal = tyre_test_longitudinal_model(tyres.mesh(r.mesh));
    } catch (const std::exception&) {  // a mesh that cannot be built fails the rig's studies when they ask
    }
    for (std::size_t i = 0; i < s.load_factors.size(); ++i)
      for (const TyreTestSeries series : kRigSeries)
        r.series.push_back(tyre_test_rolling_study(s, i, series, r.mesh, r.longitudinal));
    r.starts.resize(s.load_factors.size());
    r.vertical = tyre_test_vertical_study(s);
    r.progress = std::make_unique<TyreTestProgress>(s, r.longitudinal);
  }
  std::vector<std::optional<ChainStart>> chain_starts(chains.size());
  for (RigPlan& rig : rigs) {
    const int first = k;  // the runs: by load, longitudinal then lateral (as rig.series)
    // Each series on its own mesh (RollingStudy::mesh: the rig's, or its half for the longitudinal one).
    const auto footprint_key = [&](const RollingStudy& s) {
      return SharedFootprints::key(*s.mesh, s.support, s.target_load, s.load_tolerance);
    };
    const bool half = rig.longitudinal == TyreTestLongitudinalModel::half;
    const auto series_task = [&](std::size_t i, std::size_t j) {
      const int run = first + static_cast<int>(kRigSeries.size() * i + j);
      const RollingStudy* s = &rig.series[kRigSeries.size() * i + j];
      const std::string key = footprint_key(*s);
      // The start (the lateral series' footprint and free rolling) serves the series on its mesh.
      const bool shares_start = kRigSeries[j] == TyreTestSeries::lateral || !half;
      const std::string name = "tyre test '" + s->name + "'";
      return task(run, name, [&, run, key, r = &rig, s, i, j, shares_start](const ProgressSink& sink) {
        const auto point_done = [&] {
          if (const std::string line = r->progress->point_done(i, kRigSeries[j]); !line.empty()) sink(line);
        };
        const RollingStart* start = shares_start && r->starts[i] ? &*r->starts[i] : nullptr;
        runs[run].rolling = run_rolling(tyres.mesh(*s->mesh), c.tyre, c.inflation, c.contact, *s, sink,
                                        &tyres.inflated(*s->mesh), footprints.find(key), point_done, nullptr, start);
        footprints.keep(key, runs[run].rolling->footprint);
      });
    };
    const int vertical = first + static_cast<int>(rig.series.size());
    // The start of a series on the full model. With the longitudinal series on the half model, the start's
    // chain runs after the vertical curve's (below) and its footprint search starts from the curve's states
    // around the load, mirrored (when the curve completed and reaches the load).
    const auto start_task = [&](std::size_t i) {
      const std::size_t lateral = kRigSeries.size() * i + 1;
      const RollingStudy* s = &rig.series[lateral];
      const std::string key = footprint_key(*s);
      return task(first + static_cast<int>(lateral), "tyre test '" + s->name + "'",
                  [&, key, r = &rig, s, i, vertical, half](const ProgressSink& sink) {
                    std::vector<PathState> nearby;
                    if (half && runs[vertical].contact && runs[vertical].contact->completed)
                      nearby = load_curve_states_near(*runs[vertical].contact, tyres.mesh(tyre_test_half_mesh(r->mesh)),
                                                      tyres.mesh(*s->mesh), s->target_load);
                    r->starts[i] = solve_rolling_start(tyres.mesh(*s->mesh), c.tyre, c.inflation, c.contact, *s,
                                                       sink, &tyres.inflated(*s->mesh), footprints.find(key),
                                                       nearby.empty() ? nullptr : &nearby);
                    if (r->starts[i]->footprint.completed) footprints.keep(key, r->starts[i]->footprint);
                  });
    };
    const auto add = [&](TaskChain chain, std::optional<ChainStart> when = {}) {
      chains.push_back(std::move(chain));
      chain_starts.push_back(when);
      return chains.size() - 1;
    };
    const std::string vertical_name = "tyre test '" + rig.vertical.name + "'";
    const auto vertical_task = task(vertical, vertical_name, [&, vertical, r = &rig, half](const ProgressSink& sink) {
      const MeshSettings half_mesh = tyre_test_half_mesh(r->mesh);
      runs[vertical].contact = run_load_curve(tyres.mesh(half_mesh), c.tyre, c.inflation, c.contact, r->vertical, sink,
                                              &tyres.inflated(half_mesh), /*keep_path=*/half);
    });
    if (rig.starts.empty()) {  // (the reader asks for at least one load)
      add({vertical_task});
      k = vertical + 1;
      continue;
    }
    const std::size_t heaviest = rig.starts.size() - 1;
    if (half) {
      // The vertical curve first: the lateral series' starts on the full model begin from its states
      // (mirrored: at 5550 N on 80 × 46 the footprint in 2 solves, 7 s, instead of 11, 29 s). Meanwhile
      // the heaviest load's longitudinal series on the half model; then the lateral series, each with its
      // start, and the other longitudinal ones, heaviest first.
      const std::size_t curve = add({vertical_task});
      for (std::size_t i = heaviest + 1; i-- > 0;) {
        add({start_task(i), series_task(i, 1)}, ChainStart{curve, 1});
        add({series_task(i, 0)});
      }
      k = vertical + 1;
      continue;
    }
    // In the order taken (on 2 workers): the heaviest load's start and lateral series; meanwhile the
    // vertical curve and the next load's start, short, and then that load's longitudinal series as soon
    // as its start is solved (the two longest series side by side from the start); then the lighter
    // loads' series, each load's lateral one with its start.
    const std::size_t heaviest_start = add({start_task(heaviest), series_task(heaviest, 1)});
    add({vertical_task});
    std::optional<std::size_t> next_start;
    if (heaviest > 0) next_start = add({start_task(heaviest - 1)});
    add({series_task(heaviest, 0)}, ChainStart{heaviest_start, 1, true});
    for (std::size_t i = heaviest; i-- > 0;) {
      if (i + 1 == heaviest) {
        add({series_task(i, 1)}, ChainStart{*next_start, 1});
        add({series_task(i, 0)}, ChainStart{*next_start, 1});
      } else {
        const std::size_t own_start = add({start_task(i), series_task(i, 1)});
        add({series_task(i, 0)}, ChainStart{own_start, 1});
      }
    }
    k = vertical + 1;
  }
  const WorkerPlan plan = plan_workers(static_cast<int>(chains.size()), omp_get_max_threads());
  prefixed = plan.workers > 1;
  if (prefixed)
    report(progress, fmt::format("{} studies on {} workers at once ({} thread{} each); lines begin with the study's name",
                                 study_count, plan.workers, plan.threads_per_worker,
                                 plan.threads_per_worker > 1 ? "s" : ""));
  const auto studies_start = std::chrono::steady_clock::now();
  run_chains(chains, plan, stop, &share, chain_starts);
  const double studies_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - studies_start).count();

  // Results in the case's order.
  toml::array incomplete;
  const int rig_first_run = study_count - rig_runs;  // a tyre test reports its failures itself
  for (int i = 0; i < study_count; ++i) {
    times.add(runs[i].phase, runs[i].seconds);
    if (!runs[i].error.empty() && i < rig_first_run) incomplete.push_back(runs[i].error);
  }
  times.begin("writing the studies' results");
  ReportWriter plots(folder, progress);
  write_study_results(c, tyres, runs, folder, plots, progress, summary, incomplete);
  // The plots still rendering in the background are waited for here (a failed one is a skipped report).
  std::vector<std::string> skipped_reports = inflation_plots.skipped();
  const std::vector<std::string>& skipped_plots = plots.skipped();
  skipped_reports.insert(skipped_reports.end(), skipped_plots.begin(), skipped_plots.end());
  times.end();
  const bool completed = incomplete.empty();
  summary.insert("completed", completed);
  if (!incomplete.empty()) summary.insert("incomplete", std::move(incomplete));
  toml::array skipped;
  for (const std::string& m : skipped_reports) skipped.push_back(m);
  if (!skipped.empty()) summary.insert("skipped_reports", std::move(skipped));

  times.begin("summary and results folder");
  const double before_writing = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  summary.insert("phases", times.table());
  // The studies' phases overlap when they ran side by side: their wall time together, and how many ran at once.
  summary.insert("studies_wall_time_s", studies_s);
  summary.insert("studies_at_once_threads", plan.workers);
  summary.insert("wall_time_s", before_writing);
  write_json(folder.path("summary.json"), summary);
  // A run that stopped short leaves the last complete results as they were.
  const std::filesystem::path where = folder.commit(completed ? "" : "-incomplete");
  times.end();
  times.report(progress, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  if (plan.workers > 1)
    report(progress, fmt::format("  (the {} studies ran side by side, {} at once: {:.2f} s of wall time together)",
                                 study_count, plan.workers, studies_s));
  return {where, where / "summary.json", completed, skipped_reports};
}

}  // namespace tirefem
