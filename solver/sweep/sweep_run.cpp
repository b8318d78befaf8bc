#include "sweep/sweep_run.hpp"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <variant>

#include "core/errors.hpp"
#include "scene/scene.hpp"
#include "scene/scene_change.hpp"
#include "shpb/simulation.hpp"
#include "shpb/summary.hpp"

namespace kolsky::sweep {

namespace {

nlohmann::json failed(const std::string& kind, const std::string& error) {
  return {{"status", "failed"}, {"failure_kind", kind}, {"error", error}, {"summary", nlohmann::json::object()}};
}

std::string duration_text(double s) {
  char buf[32];
  if (s < 120) std::snprintf(buf, sizeof buf, "%.3g s", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}

/// A DEM specimen's grain counts at the start and the end (breakage, Sec. 5.3; each break is
/// -1 + 14 grains): the figures a breakage-strength sweep is about. Nothing for other specimens.
void add_grain_counts(const shpb::RunResult& r, nlohmann::json& summary) {
  if (!r.has_probe("grain_count") || r.probe("grain_count").value.empty()) return;
  const auto& g = r.probe("grain_count").value;
  summary["grains_start"] = g.front();
  summary["grains_end"] = g.back();
  summary["grain_growth_ratio"] = g.back() / g.front();
  for (const char* p : {"broken_primary", "broken_secondary"})
    if (r.has_probe(p) && !r.probe(p).value.empty()) summary[p] = r.probe(p).value.back();
}

}  // namespace

nlohmann::json run_scene(const nlohmann::json& scene_json, const std::string& file, const std::string& base_dir,
                         const MemberOptions& o) {
  // nthreads-var is per thread: this sets the member's own team size, not its neighbours'.
  if (o.omp_threads > 0) omp_set_num_threads(o.omp_threads);
  const auto stopped = [stop = o.stop] { return stop != nullptr && *stop != 0; };
  if (stopped()) throw StopRequested("stopped on request before it started; it runs on a rerun");
  const auto start = std::chrono::steady_clock::now();
  nlohmann::json out;
  try {
    scene::Scene sc = scene::parse_scene(scene_json, file, base_dir);
    if (auto* dem = std::get_if<dem::DemSpecimenParams>(&sc.spec.specimen))
      dem->packing.on_progress = [&](const dem::PackingProgress&) {  // a packing takes minutes
        if (stopped()) throw StopRequested("stopped on request while packing; it runs on a rerun");
      };
    shpb::SimulatedShpb sim(sc.spec);  // a DEM specimen packs here (or reads its cache)
    sim.require_analysable_end();
    shpb::RunControl control;
    control.stop = o.stop;
    const shpb::RunResult r = sim.run(nullptr, control);
    if (stopped()) throw StopRequested("stopped on request; it runs on a rerun");
    if (!r.complete) {
      out = failed("numerical", "numerical failure: " + r.failure);
    } else {
      const shpb::RunAnalysis a = sim.analyze(r);
      out = {{"status", "ok"}, {"failure_kind", ""}, {"error", ""}, {"summary", shpb::summarize(a.waves, a.history)}};
      add_grain_counts(r, out["summary"]);
    }
    out["steps"] = r.steps;
    out["ended_by"] = r.ended_by;
  } catch (const InputError& e) {  // the physics knows the path, the scene knows the file
    out = failed("input", InputError(e.file().empty() ? file : e.file(), e.path(), e.rule()).what());
  } catch (const NumericalError& e) {
    out = failed("numerical", std::string("numerical failure: ") + e.what());
  }
  out["run_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string member_key(const SweepPlan& plan, const SweepPoint& point) {
  return scene::content_key(member_scene(plan, point), "kolsky sweep member\n" + scene_folder(plan));
}

std::vector<ensemble::EnsembleMember> sweep_members(const SweepPlan& plan, const std::vector<SweepPoint>& points,
                                                    const MemberOptions& options) {
  std::vector<ensemble::EnsembleMember> out;
  const std::string dir = scene_folder(plan);
  for (const SweepPoint& p : points) {
    ensemble::EnsembleMember m;
    m.label = p.label;
    m.key = member_key(plan, p);
    m.run = [scene = member_scene(plan, p), file = plan.scene_file, dir, options] {
      return run_scene(scene, file, dir, options);
    };
    out.push_back(std::move(m));
  }
  return out;
}

MemberOutcome outcome(const ensemble::MemberResult& r) {
  MemberOutcome o;
  o.cached = r.cached;
  if (!r.ok) {
    o.failure_kind = "error";
    o.error = r.error;
    o.run_s = r.wall_s;
    return o;
  }
  o.ok = r.value.value("status", "") == "ok";
  o.failure_kind = r.value.value("failure_kind", "");
  o.error = r.value.value("error", "");
  o.run_s = r.value.value("run_s", 0.0);
  return o;
}

double eta_seconds(double elapsed_s, std::size_t run, std::size_t remaining) {
  if (run == 0) return remaining == 0 ? 0 : -1;
  return elapsed_s / static_cast<double>(run) * static_cast<double>(remaining);
}

std::string progress_line(const ensemble::MemberResult& r, std::size_t done, std::size_t total, double elapsed_s,
                          std::size_t run) {
  const MemberOutcome o = outcome(r);
  const double eta = eta_seconds(elapsed_s, run, total - done);
  std::string line = "kolsky sweep: " + std::to_string(done) + "/" + std::to_string(total) + " done (" + r.label +
                     ": " + (o.ok ? "ok" : "FAILED") + (o.cached ? ", from the cache" : ", " + duration_text(o.run_s)) +
                     "), elapsed " + duration_text(elapsed_s);
  if (done < total) line += eta < 0 ? ", time left not known yet" : ", about " + duration_text(eta) + " left";
  return line;
}

}  // namespace kolsky::sweep
