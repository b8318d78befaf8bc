// `kolsky sweep SCENE.json --set KEY=VALUES [--set ...] [--seeds K] [--threads N] [-o TABLE]
//  [--plot DIR] [--quiet]`: the scene run once per member of the product of every key's values
// and the packing seeds (solver/sweep/), on N threads or, under mpirun, on the ranks; one table
// of the members' summary figures (TABLE stem + .csv and .h5), cached members by content key
// in TABLE stem + .cache/ so that a killed sweep resumes. Every member's scene is checked
// before any runs (exit 2). Failed members are rows; the exit code says the worst: 3 for a
// numerical failure, 2 for a member the solver refused, 1 for anything else.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "app/plot_output.hpp"
#include "app/run_checks.hpp"
#include "core/errors.hpp"
#include "ensemble/ensemble.hpp"
#include "sweep/sweep_plots.hpp"
#include "sweep/sweep_run.hpp"
#include "sweep/sweep_table.hpp"

namespace kolsky::app {

namespace {

/// TABLE with a trailing .csv or .h5 taken off (both files are written); by default the scene's
/// stem + "_sweep" in the working folder, as `kolsky run` names its output.
std::string table_stem(const std::string& output, const std::string& scene_file) {
  if (output.empty()) return std::filesystem::path(scene_file).stem().string() + "_sweep";
  for (const std::string ext : {".csv", ".h5"})
    if (output.size() > ext.size() && output.ends_with(ext)) return output.substr(0, output.size() - ext.size());
  return output;
}

int exit_code(const std::vector<ensemble::MemberResult>& results) {
  int code = 0;
  for (const auto& r : results) {
    const sweep::MemberOutcome o = sweep::outcome(r);
    if (o.failure_kind == "numerical") code = kExitNumericalError;
    else if (o.failure_kind == "input" && code != kExitNumericalError) code = kExitInputError;
    else if (o.failure_kind == "error" && code == 0) code = 1;
  }
  return code;
}

int sweep(const Options& o, bool root) {
  const std::string& file = o.positional[0];
  const std::string gnuplot = o.plot_dir.empty() ? "" : prepare_plots(o.plot_dir);
  std::vector<sweep::SweepAxis> axes;
  for (const std::string& s : o.sets) axes.push_back(sweep::parse_axis(s));
  const sweep::SweepPlan plan = sweep::make_plan(file, std::move(axes), o.seeds);
  const std::vector<sweep::SweepPoint> points = sweep::sweep_points(plan);
  const std::string stem = table_stem(o.output, file);
  const std::string csv = stem + ".csv", h5 = stem + ".h5", cache = stem + ".cache";
  check_outputs({{"-o", csv}, {"-o", h5}}, {file});
  if (std::filesystem::exists(cache) && !std::filesystem::is_directory(cache))
    throw InputError("-o", "", "the sweep's cache folder '" + cache + "' is a file");
  sweep::validate_points(plan, points);  // every member's scene, before any runs

  const int threads = std::max(1, o.threads);
  const ensemble::RankLayout layout = ensemble::rank_layout();
  const std::string where = layout.size > 1 ? std::to_string(layout.size) + " MPI ranks"
                                             : std::to_string(threads) + " at once";
  if (root && !o.quiet)
    std::fprintf(stderr, "kolsky sweep: %s: %zu members, %s, cache %s/\n", file.c_str(), points.size(),
                 where.c_str(), cache.c_str());
  const InterruptGuard interrupts;  // SIGINT/SIGTERM: members stop at their next step
  sweep::MemberOptions mo;
  mo.stop = interrupt_flag();
  if (threads > 1) mo.omp_threads = std::max(1, omp_get_max_threads() / threads);
  ensemble::EnsembleOptions eo;
  eo.threads = threads;
  eo.cache_dir = cache;
  const auto start = std::chrono::steady_clock::now();
  std::size_t run = 0;
  if (root && !o.quiet)
    eo.on_done = [&](const ensemble::MemberResult& r, std::size_t done, std::size_t total) {
      if (!r.cached) ++run;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "%s\n", sweep::progress_line(r, done, total, elapsed, run).c_str());
    };
  const auto results = ensemble::run_ensemble(sweep::sweep_members(plan, points, mo), eo);

  const int code = exit_code(results);
  if (!root) return interrupt_signal() ? 128 + interrupt_signal() : code;
  const sweep::SweepTable table = sweep::make_table(plan, points, results);
  sweep::write_table_csv(csv, table);
  sweep::write_table_hdf5(h5, table);
  const auto failed = static_cast<std::size_t>(
      std::count(table.column("status").texts.begin(), table.column("status").texts.end(), "failed"));
  std::printf("kolsky sweep: %s: %zu members, %zu ok, %zu failed -> %s, %s\n", file.c_str(), table.rows,
              table.rows - failed, failed, csv.c_str(), h5.c_str());
  if (!o.plot_dir.empty()) write_plots(sweep::sweep_figures(table, file), o.plot_dir, gnuplot, "sweep");
  if (interrupt_signal()) {
    std::fprintf(stderr, "kolsky sweep: %s: the members not finished run on a rerun (cache %s/)\n",
                 interrupt_name(), cache.c_str());
    return 128 + interrupt_signal();
  }
  if (code != 0) std::fprintf(stderr, "kolsky sweep: failed members: %zu (status and error in %s)\n", failed, csv.c_str());
  return code;
}

}  // namespace

int cmd_sweep(const std::vector<std::string>& args) {
  const Options o = parse_options(args, {"-o", "--set", "--seeds", "--threads", "--plot", "--quiet"});
  if (o.positional.size() != 1) throw UsageError("needs exactly one SCENE.json");
  if (o.sets.empty() && o.seeds == 0) throw UsageError("needs --set KEY=VALUES or --seeds K: nothing to vary");
  // Every rank checks the same input; only rank 0 reports (one line, not one per rank).
  const bool root = ensemble::rank_layout().rank == 0;
  try {
    return sweep(o, root);
  } catch (const InputError&) {
    if (root) throw;
    return kExitInputError;
  }
}

}  // namespace kolsky::app
