#include "harness/case_pipeline.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <variant>

#include "core/errors.hpp"
#include "core/table.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"

namespace kolsky::harness {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Case Case::with(const std::string& key, const nlohmann::json& value, const std::string& new_label) const {
  Case c = *this;
  c.changes.push_back({key, value});
  c.label = new_label;
  return c;
}

nlohmann::json final_scene(const Case& c) {
  nlohmann::json j = c.scene;
  if (!c.packing_cache.empty())
    j["specimen"]["packing_cache"] = std::filesystem::absolute(c.packing_cache).string();
  for (const auto& ch : c.changes) apply_change(j, ch, c.scene_path);
  return j;
}

std::string scene_dir(const Case& c) { return std::filesystem::path(c.scene_path).parent_path().string(); }

void validate(const Case& c) { scene::parse_scene(final_scene(c), c.scene_path, scene_dir(c)); }

std::string content_key(const Case& c) { return scene::content_key(final_scene(c)); }

std::string packing_key(const Case& c) {
  const auto sc = scene::parse_scene(final_scene(c), c.scene_path, scene_dir(c));
  const auto* dp = std::get_if<dem::DemSpecimenParams>(&sc.spec.specimen);
  return dp == nullptr ? "" : dem::packing_cache_key(dp->packing);
}

dem::CachedPacking pack(const Case& c) {
  const auto sc = scene::parse_scene(final_scene(c), c.scene_path, scene_dir(c));
  const auto* dp = std::get_if<dem::DemSpecimenParams>(&sc.spec.specimen);
  if (dp == nullptr) throw InputError(c.scene_path, "specimen.model", "not a DEM specimen: there is no packing");
  dem::PackingParams p = dp->packing;
  p.on_progress = [label = c.label](const dem::PackingProgress& q) {
    const std::string phase = q.phase;
    const bool staged = phase == "growth" || phase == "compaction" || phase == "settle";
    if (q.done % (staged ? 10 : 20) != 0 && q.done != q.most) return;
    std::printf("%s: %s %d (of at most %d), %s %.3g", label.c_str(), q.phase, q.done, q.most,
                phase == "growth"       ? "radius scale"
                : phase == "compaction" ? "wall gap / length"
                : phase == "settle"     ? "largest overlap / mean radius"
                : phase == "relax"      ? "kinetic / initial elastic energy"
                                        : "wall mean stress (Pa)",
                q.value);
    if (phase != "prestress" && std::isfinite(q.wall_stress)) std::printf(", wall mean stress %.3g Pa", q.wall_stress);
    if (std::isfinite(q.coordination)) std::printf(", Z %.2f", q.coordination);
    std::printf("\n");
  };
  return dem::cached_packing(p, dp->packing_store);
}

std::vector<double> from_arrival(const shpb::RunResult& run, const std::string& probe) {
  const auto& v = run.probe(probe).value;
  std::vector<double> out;
  for (std::size_t i = 0; i < run.t.size(); ++i)
    if (!(run.t[i] < run.arrival_time - 1e-12)) out.push_back(v[i]);
  return out;
}

std::vector<double> on_history(const CaseOutputs& out, const std::string& probe) {
  const Table1D on_run{out.run.t, out.run.probe(probe).value};
  std::vector<double> v(out.history.t.size());
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = on_run(out.history.t[k] + out.run.arrival_time);
  return v;
}

namespace {

DemFinalState dem_final_state(const dem::DemSpecimen& d) {
  DemFinalState s;
  const auto& p = d.system().particles();
  s.grains = p.size();
  s.held_steps = d.held_calls();
  double solid = 0;
  for (double r : p.radius) solid += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  s.porosity = 1 - solid / (d.area() * d.length());
  s.grain_volume = solid;
  s.face_area = d.area();
  return s;
}

GaugeRecord gauge_record(const shpb::RunResult& run, const shpb::ExperimentSpec& spec) {
  GaugeRecord g;
  if (!run.has_probe("incident_gauge_strain")) return g;
  const double e_i = spec.incident.material.youngs_modulus, e_t = spec.transmission.material.youngs_modulus;
  g.t = run.t;
  for (double e : run.probe("incident_gauge_strain").value) g.incident.push_back(-e * e_i);
  for (double e : run.probe("transmission_gauge_strain").value) g.transmission.push_back(-e * e_t);
  return g;
}

/// Case::progress_lines: a line per part of the run, with the wall time since `run_start`.
void add_progress(const Case& c, const shpb::SimulatedShpb& sim, double end_time,
                  const std::chrono::steady_clock::time_point& run_start, shpb::RunControl& control) {
  if (c.progress_lines <= 0) return;
  control.progress_every = std::max(1L, sim.schedule().n_steps / c.progress_lines);
  control.progress = [label = c.label, end_time, &run_start](long, double t) {
    std::printf("  %s: %.0f %% (t = %.1f us, %.0f s)\n", label.c_str(), 100.0 * t / end_time, t * 1e6,
                seconds_since(run_start));
  };
}

/// The run and what is read off it; throws what the solver throws.
void build_and_run(const Case& c, const scene::Scene& sc, std::chrono::steady_clock::time_point start,
                   CaseOutputs& out) {
  shpb::SimulatedShpb sim(sc.spec);  // a DEM specimen packs here (or reads its cache)
  out.build_s = seconds_since(start);
  sim.require_analysable_end();
  shpb::RunControl control;
  if (c.grain_size_curve_every > 0) {
    control.snapshot_every = std::max(1L, std::lround(c.grain_size_curve_every / sim.schedule().dt));
    control.grain_size_curve = [&out](long, double t, const psd::GrainSizeCurve& g) { out.curves.push_back({t, g}); };
  }
  std::chrono::steady_clock::time_point run_start;  // the progress lines read it when they print
  add_progress(c, sim, sc.spec.time.end_time, run_start, control);
  run_start = std::chrono::steady_clock::now();
  out.run = sim.run(nullptr, control);
  out.run_s = seconds_since(run_start);
  out.gauges = gauge_record(out.run, sc.spec);
  if (const dem::DemSpecimen* d = sim.dem_specimen()) out.dem = dem_final_state(*d);
  if (!out.run.complete) {
    out.failure = out.run.failure;
    return;
  }
  try {  // a run too short for the wave analysis keeps its face records
    shpb::RunAnalysis a = sim.analyze(out.run);
    out.history = std::move(a.history);
    out.waves = std::move(a.waves);
  } catch (const std::invalid_argument& e) {
    out.analysis_failure = e.what();
  }
  for (std::size_t i = 0; i < out.run.t.size(); ++i)
    if (!(out.run.t[i] < out.run.arrival_time - 1e-12)) out.faces.t.push_back(out.run.t[i] - out.run.arrival_time);
  out.faces.front = from_arrival(out.run, "stress_front");
  out.faces.back = from_arrival(out.run, "stress_back");
  out.faces.strain = from_arrival(out.run, "specimen_strain");
  out.ok = true;
}

}  // namespace

CaseOutputs run_case(const Case& c) {
  CaseOutputs out;
  out.label = c.label;
  const auto start = std::chrono::steady_clock::now();
  try {
    out.content_key = content_key(c);
    const auto sc = scene::parse_scene(final_scene(c), c.scene_path, scene_dir(c));
    build_and_run(c, sc, start, out);
  } catch (const InputError& e) {
    out.failure = e.what();
    out.refusal = std::current_exception();
  } catch (const std::exception& e) {
    out.failure = e.what();
  }
  out.wall_s = seconds_since(start);
  return out;
}

}  // namespace kolsky::harness
