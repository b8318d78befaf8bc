// `kolsky run SCENE.json [-o OUT.h5] [--gauges-csv G.csv] [--plot DIR] [--threads N] [--quiet]
//  [--checkpoint-every S [--checkpoint-file CK.h5]] [--restart CK.h5]`: builds the scene's SHPB
// assembly (shpb/assembly.hpp), runs it, and writes its probes by name plus the classic
// analysis of the face waves (strain-rate walls: the direct analysis of the wall stresses) and,
// with --plot, their figures.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "app/plot_output.hpp"
#include "app/run_checks.hpp"
#include "core/progress.hpp"
#include "io/checkpoint_hdf5.hpp"
#include "io/csv.hpp"
#include "io/hdf5_run.hpp"
#include "io/snapshots.hpp"
#include "plot/shpb_figures.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"
#include "shpb/summary.hpp"
#include "core/build_info.hpp"

namespace kolsky::app {

namespace {

// Probes plus the run's analysis (of the face waves, or direct for strain-rate walls), on the
// run's clock; analysis series the history does not have (no wave energies in a direct
// analysis) are left out.
io::RunRecord to_record(const scene::Scene& sc, const shpb::RunResult& r,
                        const shpb::SpecimenHistory& h, const nlohmann::json& summary) {
  io::RunRecord rec;
  rec.meta["scene"] = sc.resolved;
  rec.meta["scene_file"] = sc.file;
  rec.meta["git_commit"] = build_info::git_commit();
  rec.meta["build_type"] = build_info::build_type();
  rec.meta["kolsky_version"] = build_info::version();
  rec.meta["complete"] = r.complete;
  rec.meta["failure"] = r.failure;
  if (!r.ended_by.empty()) rec.meta["ended_by"] = r.ended_by;  // loading.end_at_back_stress
  rec.meta["dt_s"] = r.dt;
  rec.meta["stable_dt_s"] = r.stable_dt;
  rec.meta["dt_final_s"] = r.dt_final;  // below dt_s when breaks refined the step
  rec.meta["dt_refinements"] = r.dt_refinements;
  rec.meta["steps"] = r.steps;
  rec.meta["arrival_time_s"] = r.arrival_time;
  rec.meta["summary"] = summary;
  for (const auto& p : r.probes) rec.probes.push_back({p.name, p.unit, r.t, p.value});
  std::vector<double> t;
  for (double x : h.t) t.push_back(x + r.arrival_time);
  const std::pair<const char*, const std::vector<double>*> analysed[] = {
      {"analysis_strain", &h.strain},           {"analysis_strain_rate", &h.strain_rate},
      {"analysis_stress_front", &h.stress_front}, {"analysis_stress_back", &h.stress_back},
      {"analysis_stress_avg", &h.stress_avg},   {"analysis_alpha", &h.alpha},
      {"analysis_dissipation_percent", &h.dissipation_percent}};
  const char* units[] = {"1", "1/s", "Pa", "Pa", "Pa", "1", "%"};
  for (size_t k = 0; k < std::size(analysed); ++k)
    if (!t.empty() && analysed[k].second->size() == t.size())
      rec.probes.push_back({analysed[k].first, units[k], t, *analysed[k].second});
  return rec;
}

/// A restart must continue the same physics and probe cadence; only time.end (to run further)
/// and output.snapshot_interval (no effect on the state) may change. Throws InputError naming
/// the checkpoint and the first key that differs.
void check_same_scene(const std::string& checkpoint, const nlohmann::json& saved,
                      const nlohmann::json& current) {
  auto without_end = [](nlohmann::json j) {
    if (j.is_object() && j.contains("time") && j["time"].is_object()) j["time"].erase("end");
    if (j.is_object() && j.contains("output") && j["output"].is_object())
      j["output"].erase("snapshot_interval");
    return j;
  };
  const nlohmann::json patch = nlohmann::json::diff(without_end(saved), without_end(current));
  if (patch.empty()) return;
  std::string key = patch[0].value("path", std::string());
  std::replace(key.begin(), key.end(), '/', '.');
  if (!key.empty() && key[0] == '.') key.erase(0, 1);
  throw InputError(checkpoint, "scene",
                   "the checkpoint was written for another scene (" +
                       (key.empty() ? std::string("scene") : key) +
                       " differs); only time.end and output.snapshot_interval may change on a "
                       "restart");
}

/// The simulated gauge record (first gauge of each bar) in the input format of `kolsky analyze`.
void write_gauges_csv(const std::string& path, const scene::Scene& sc, const shpb::RunResult& r) {
  io::CsvTable g;
  g.header = {"time_s", "incident_strain", "transmitted_strain"};
  g.columns = {r.t, r.probe(shpb::gauge_probe_name("incident", 0)).value,
               r.probe(shpb::gauge_probe_name("transmission", 0)).value};
  // A stopped or failed run's record is partial: its first comment says so, and `kolsky
  // analyze` refuses it without --allow-incomplete (an analysis of a cut record looks complete).
  const std::string mark = r.complete ? "" : std::string(kIncompleteRecordMark) + " (" + r.failure +
                                                 "): the record ends early\n";
  io::write_csv(path, g, mark +
                "simulated gauge record of " + sc.file + " (strain as measured: compression "
                "negative); gauges at " + std::to_string(sc.spec.incident.gauges.front()) +
                " m (incident) and " + std::to_string(sc.spec.transmission.gauges.front()) +
                " m (transmission) from the specimen faces");
}

/// Steps per interval of `seconds`, at least 1 (the probe cadence rounds the same way), at
/// most `steps` (an interval beyond the run acts once, and must not overflow a long).
long steps_per(double seconds, double dt, long steps) {
  const double n = std::min(std::round(seconds / dt), static_cast<double>(steps));
  return std::max(1L, static_cast<long>(n));
}

/// The files one run names: the scene, the run file and the checkpoint file.
struct RunFiles {
  std::string scene, out, checkpoint;
};

RunFiles run_files(const Options& o) {
  RunFiles f;
  f.scene = o.positional[0];
  f.out = o.output.empty() ? std::filesystem::path(f.scene).stem().string() + ".h5" : o.output;
  const std::filesystem::path out(f.out);
  f.checkpoint = !o.checkpoint_file.empty() ? o.checkpoint_file
                                             : (out.parent_path() / out.stem()).string() + ".ckpt.h5";
  return f;
}

/// Everything that can be checked without the assembly, checked before it is built (a DEM
/// packing takes minutes): every output path, the end time against the wave's arrival, a
/// checkpoint request against the specimen model.
void check_before_building(const Options& o, const scene::Scene& sc, const RunFiles& f) {
  if (!o.gauges_csv.empty() && sc.spec.strain_rate)
    throw InputError(f.scene, "loading.kind",
                     "--gauges-csv: strain-rate walls (loading.kind = strain_rate) have no bars, "
                     "hence no gauge record");
  std::vector<OutputPath> outputs = {{"-o", f.out}};
  if (!o.gauges_csv.empty()) outputs.push_back({"--gauges-csv", o.gauges_csv});
  if (o.checkpoint_every > 0)
    outputs.push_back({o.checkpoint_file.empty() ? "--checkpoint-every" : "--checkpoint-file", f.checkpoint});
  if (sc.spec.output.snapshot_interval > 0) {  // beside OUT, named after it
    const auto [h5, xmf] = io::snapshot_paths(f.out);
    outputs.push_back({"-o (particle snapshots)", h5});
    outputs.push_back({"-o (particle snapshots)", xmf});
  }
  std::vector<std::string> inputs = scene_inputs(sc);
  if (!o.restart.empty()) inputs.push_back(o.restart);
  // A checkpoint may replace the one the run restarts from: it has been read by then.
  if (o.checkpoint_every > 0 && !o.restart.empty()) inputs.pop_back();
  check_outputs(outputs, inputs);
  try {
    shpb::require_reachable_end(sc.spec);
  } catch (const InputError& e) {
    throw InputError(f.scene, e.path(), e.rule());
  }
  if (o.checkpoint_every > 0 && std::holds_alternative<fe::FeSpecimenParams>(sc.spec.specimen))
    throw InputError(f.scene, "specimen.model",
                     "--checkpoint-every: checkpoints are not available for the fe specimen");
}

/// A DEM specimen is packed (or read from its cache) while the simulation is built: minutes
/// at N = 2, tens of minutes at N = 1. A bar per phase on a terminal; a signal stops it after
/// the stage in progress (nothing is written then: there is no run yet).
struct PackingBars {
  bool shown = false;
  std::optional<Progress> bar;
  std::string phase;
};

std::unique_ptr<shpb::SimulatedShpb> build_simulation(scene::Scene& sc, PackingBars& bars) {
  if (auto* dem_params = std::get_if<dem::DemSpecimenParams>(&sc.spec.specimen))
    dem_params->packing.on_progress = [&bars](const dem::PackingProgress& p) {
      if (interrupt_signal()) throw StopRequested("stopped on request while packing; nothing written");
      if (!bars.shown) return;
      if (bars.phase != p.phase) {
        if (bars.bar) bars.bar->finish();
        bars.phase = p.phase;
        bars.bar.emplace(p.most, true, "kolsky packing, " + bars.phase + " ");
      }
      bars.bar->update(p.done);
    };
  try {
    auto sim = std::make_unique<shpb::SimulatedShpb>(sc.spec);
    if (bars.bar) bars.bar->finish();
    sim->require_analysable_end();
    return sim;
  } catch (const InputError& e) {  // the physics knows the path, the scene knows the file
    throw InputError(sc.file, e.path(), e.rule());
  }
}

/// Checkpoint, restart and particle snapshots: hooks of the run loop (shpb::RunControl). The
/// hooks refer to this struct's members: it stays where it was made.
struct RunHooks {
  shpb::RunControl control;
  std::unique_ptr<io::SnapshotWriter> snapshots;
  io::CsvTable curves;  ///< breaking grains: the grain-size curves at the snapshot times
};

void set_up_hooks(RunHooks& h, const Options& o, const scene::Scene& sc, shpb::SimulatedShpb& sim,
                  const RunFiles& f, const std::optional<io::Checkpoint>& resume) {
  const long n_steps = sim.schedule().n_steps;
  const double dt = sim.schedule().dt;
  h.control.stop = interrupt_flag();
  if (resume) h.control.resume = &resume->state;
  if (o.checkpoint_every > 0) {
    if (!sim.can_checkpoint())  // the FE parts have no checkpoint state
      throw InputError(f.scene, "specimen.model",
                       "--checkpoint-every: checkpoints are not available for this model (an fe specimen, or FE "
                       "parts around a dem specimen: bars.kind = meshed or specimen.tube = meshed)");
    h.control.checkpoint_every = steps_per(o.checkpoint_every, dt, n_steps);
    const nlohmann::json meta = {{"scene", sc.resolved}, {"scene_file", sc.file},
                                 {"git_commit", build_info::git_commit()}, {"kolsky_version", build_info::version()}};
    h.control.checkpoint = [file = f.checkpoint, meta](const shpb::ShpbState& s) {
      io::write_checkpoint_hdf5(file, {meta, s});
    };
  }
  if (sc.spec.output.snapshot_interval <= 0) return;
  const auto [h5, xmf] = io::snapshot_paths(f.out);
  h.snapshots = std::make_unique<io::SnapshotWriter>(h5, xmf);
  h.control.snapshot_every = steps_per(sc.spec.output.snapshot_interval, dt, n_steps);
  h.control.snapshot = [&h](long n, double t, const dem::Particles& p) { h.snapshots->add(n, t, p); };
  // Breaking grains: the grain-size curve (grains + fines) at the same times, one CSV table.
  h.curves.header = {"time_s", "diameter_m", "percent_passing"};
  h.curves.columns.resize(3);
  h.control.grain_size_curve = [&h](long, double t, const psd::GrainSizeCurve& c) {
    for (std::size_t k = 0; k < c.size(); ++k) {
      h.curves.columns[0].push_back(t);
      h.curves.columns[1].push_back(c.diameter[k]);
      h.curves.columns[2].push_back(c.percent_passing[k]);
    }
  };
}

/// The outputs beside the run file; returns what failed ("" when all were written). A file
/// says complete = 1 only when the run completed and every output before it was written.
std::string write_siblings(const Options& o, const scene::Scene& sc, const RunFiles& f,
                           const shpb::RunResult& r, RunHooks& h) {
  std::string failure;
  if (!o.gauges_csv.empty()) {
    try {
      write_gauges_csv(o.gauges_csv, sc, r);
    } catch (const std::exception& e) {
      failure = std::string("--gauges-csv: ") + e.what();
    }
  }
  if (!h.curves.columns.empty() && !h.curves.columns[0].empty()) {
    try {  // breaking grains: the grain-size curves at the snapshot times (docs/breakage.md)
      const std::string& out = f.out;
      const std::string stem = out.substr(0, out.size() - (out.size() > 3 && out.ends_with(".h5") ? 3 : 0));
      io::write_csv(stem + ".grain_size_curves.csv", h.curves,
                    "grain-size curves of " + f.scene + " (grains + Eq. 5.16 fines, docs/breakage.md) at the "
                    "snapshot times" + std::string(r.complete ? "" : "; INCOMPLETE run"));
    } catch (const std::exception& e) {
      if (failure.empty()) failure = std::string("grain-size curves: ") + e.what();
    }
  }
  if (h.snapshots) {
    try {
      h.snapshots->finish(r.complete && failure.empty());  // kept, complete = 0, after a blow-up
    } catch (const std::exception& e) {
      if (failure.empty()) failure = std::string("particle snapshots: ") + e.what();
    }
  }
  return failure;
}

/// The exit status, with its reason on stderr: 1 for a failed output, 128 + the signal after
/// SIGINT or SIGTERM (as a shell reports a killed command), 3 for a numerical failure.
int exit_status(const shpb::RunResult& r, const std::string& out, const std::string& output_failure,
                int stop_signal) {
  if (!output_failure.empty()) {
    std::fprintf(stderr, "kolsky run: error: %s; %s kept, marked incomplete\n", output_failure.c_str(),
                 out.c_str());
    return 1;
  }
  if (stop_signal) {
    if (r.complete)
      std::fprintf(stderr, "kolsky run: %s after the last step; %s is complete\n", interrupt_name(),
                   out.c_str());
    else
      std::fprintf(stderr, "kolsky run: %s: %s; output kept in %s, marked incomplete\n",
                   interrupt_name(), r.failure.c_str(), out.c_str());
    return 128 + stop_signal;
  }
  if (!r.complete) {
    std::fprintf(stderr, "kolsky: numerical failure: %s; output kept in %s, marked incomplete\n",
                 r.failure.c_str(), out.c_str());
    return kExitNumericalError;
  }
  return 0;
}

}  // namespace

int cmd_run(const std::vector<std::string>& args) {
  const Options o = parse_options(args, {"-o", "--threads", "--quiet", "--gauges-csv", "--plot",
                                         "--checkpoint-every", "--checkpoint-file", "--restart"});
  if (!o.checkpoint_file.empty() && o.checkpoint_every <= 0)
    throw UsageError("--checkpoint-file needs --checkpoint-every");
  if (o.positional.size() != 1) throw UsageError("needs exactly one SCENE.json");
  const InterruptGuard interrupts;  // SIGINT/SIGTERM: stop at the next step, keep the output
  const std::string gnuplot = o.plot_dir.empty() ? "" : prepare_plots(o.plot_dir);
  const RunFiles f = run_files(o);
  if (o.threads > 0) omp_set_num_threads(o.threads);
  scene::Scene sc = scene::load_scene(f.scene);
  check_before_building(o, sc, f);
  std::optional<io::Checkpoint> resume;
  if (!o.restart.empty()) {  // the restart file against the scene, before the build too
    resume = io::read_checkpoint_hdf5(o.restart);
    check_same_scene(o.restart, resume->meta.value("scene", nlohmann::json()), sc.resolved);
  }
  PackingBars packing_bars{!o.quiet && stderr_is_terminal(), {}, {}};
  const std::unique_ptr<shpb::SimulatedShpb> sim = build_simulation(sc, packing_bars);
  if (!o.quiet)
    std::fprintf(stderr, "kolsky run: %s: %ld steps of %.4g s (stable limit %.4g s)\n",
                 f.scene.c_str(), sim->schedule().n_steps, sim->schedule().dt,
                 sim->schedule().stable_dt);
  const nlohmann::json initial_wall_stress = report_initial_wall_stress(*sim, sc, o.quiet);
  warn_probe_size(*sim, f.out);
  RunHooks hooks;
  set_up_hooks(hooks, o, sc, *sim, f, resume);

  Progress progress(sc.spec.time.end_time, !o.quiet && stderr_is_terminal(), "kolsky run ");
  const auto start = std::chrono::steady_clock::now();
  shpb::RunResult r;
  try {
    r = sim->run(&progress, hooks.control);
  } catch (const InputError& e) {  // a checkpoint that does not fit names the checkpoint
    const bool from_checkpoint = resume && e.path() != "specimen.model";
    throw InputError(from_checkpoint ? o.restart : f.scene, e.path(), e.rule());
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int stop_signal = interrupt_signal();

  // Bars: the wave analysis of the face waves; strain-rate walls: the direct one (no waves).
  // A run stopped by a numerical failure before the analysis has its two samples (the
  // incident wave not yet at the specimen) is written without one: its probes and failure
  // are the result, and the analysis of too short a record must not replace them.
  const bool analysed = r.complete || sim->can_analyze(r);
  const shpb::RunAnalysis analysis = analysed ? sim->analyze(r) : shpb::RunAnalysis{};
  const auto summary = shpb::summarize(analysis.waves, analysis.history);
  io::RunRecord rec = to_record(sc, r, analysis.history, summary);
  if (resume) rec.meta["restarted_from"] = o.restart;
  if (!initial_wall_stress.is_null()) rec.meta["initial_wall_stress_pa"] = initial_wall_stress;
  if (hooks.snapshots) rec.meta["snapshots"] = io::snapshot_paths(f.out).first;
  // Siblings first and the run file last; a failed sibling is named in the run file's /meta
  // (output_failure), the rest is kept, and the command exits 1.
  const std::string output_failure = write_siblings(o, sc, f, r, hooks);
  rec.meta["complete"] = r.complete && output_failure.empty();
  if (!output_failure.empty()) rec.meta["output_failure"] = output_failure;
  io::write_run_hdf5(f.out, rec);

  std::printf("kolsky run: %s -> %s (%s)\n", f.scene.c_str(), f.out.c_str(),
              rec.meta["complete"].get<bool>() ? "complete" : "INCOMPLETE");
  std::printf("  %-26s %ld\n  %-26s %.6g\n  %-26s %.3g\n", "steps", r.steps, "dt_s", r.dt,
              "wall_time_s", wall);
  if (r.dt_refinements > 0)
    std::printf("  %-26s %.6g (refined %ld times after breaks)\n", "dt_final_s", r.dt_final,
                r.dt_refinements);
  if (!r.ended_by.empty()) std::printf("  %-26s %s\n", "ended_by", r.ended_by.c_str());
  std::fputs(shpb::format_summary(summary).c_str(), stdout);
  if (!o.plot_dir.empty() && analysed)
    write_plots(plot::run_figures(r, analysis.waves, analysis.history, f.scene), o.plot_dir, gnuplot, "run");
  else if (!o.plot_dir.empty())
    std::fprintf(stderr, "kolsky run: no plots: the run stopped before the analysis had two samples\n");
  return exit_status(r, f.out, output_failure, stop_signal);
}

}  // namespace kolsky::app
