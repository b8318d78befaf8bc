// Steps 1 and 2 of the Chapter 4 recipe: the inputs and the packing.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "chapter4/recipe.hpp"
#include "common/perturb.hpp"
#include "common/report_input.hpp"
#include "harness/targets.hpp"

namespace kolsky::ch4 {

using repro::fmt;

bool study_on(const std::string& name) {
  const char* env = std::getenv("KOLSKY_CH4_STUDIES");
  const std::string list = "," + std::string(env ? env : "twin,calibration,jammed") + ",";
  return list.find("," + name + ",") != std::string::npos;
}

CalPoint run_point(const Recipe& r, const harness::Case& c, double k, const std::string& label) {
  const CaseResult cr = run_case(c, k, label);
  const Measures q = measure(cr, 1e6, 3e6, r.limit);
  std::printf("%s: %s, %.1f s, M 1-3 MPa %.1f MPa, 7-10 MPa %.1f MPa\n", label.c_str(),
              cr.ok ? "ok" : cr.failure.c_str(), cr.wall_s, q.modulus_initial / 1e6, q.modulus_late / 1e6);
  return cal_point(cr, q, false);
}

namespace {

// The set's case: the scale's scene with the packing cache next to the report (reused by the
// later cases and by a re-run into the same folder) and the diagnostic overrides, each named
// in the report's preamble.
void set_case(Recipe& r) {
  harness::Case& c = r.set_case;
  c.label = "packing N";
  c.scene_path = r.args.set_dir() + "/scene_" + r.args.scale + ".json";
  c.scene = repro::read_scene_json(c.scene_path, r.args.perturb_seed);
  c.packing_cache = std::filesystem::absolute(r.rep.out_dir + "/packing_cache").string();
  // KOLSKY_CH4_SET="specimen.packing=\"servo_walls\";specimen.upscale=3": diagnostic scene
  // overrides (README, "The preparation study"); the report's preamble lists them.
  r.override_note = apply_scene_overrides(c, std::getenv("KOLSKY_CH4_SET"));
  // KOLSKY_CH4_POROSITY: a diagnostic override of the specimen porosity (README, "A specimen
  // that starts jammed"); the report then says so, and the porosity target fails.
  if (const char* env = std::getenv("KOLSKY_CH4_POROSITY")) {
    c.changes.push_back({"specimen.porosity", std::stod(env)});
    r.override_note += "**Diagnostic run: specimen porosity overridden to " + std::string(env) +
                       " by KOLSKY_CH4_POROSITY (the text's is 0.44).**\n\n";
  }
  // KOLSKY_CH4_RELAX_TO_REST=1: the specimen relaxed to rest under the run's law before the
  // run (specimen.relax_to_rest; README, "A specimen at rest"), a diagnostic until the
  // preparation study settles the chapter's default.
  if (const char* env = std::getenv("KOLSKY_CH4_RELAX_TO_REST"); env && std::string(env) == "1") {
    c.changes.push_back({"specimen.relax_to_rest", true});
    r.override_note += "**Diagnostic run: the specimen relaxed to rest before the run "
                       "(KOLSKY_CH4_RELAX_TO_REST=1; the chapter's scenes do not).**\n\n";
  }
  r.upscale = harness::final_scene(c)["specimen"]["upscale"].get<double>();
  c.label = "packing N = " + fmt("%g", r.upscale);
}

}  // namespace

// 1. Inputs. The thresholds and printed values are read before any run, so that a missing
// one fails in seconds, not after the packing.
Recipe read_inputs(const repro::DriverArgs& args) {
  Recipe r;
  r.args = args;
  r.smoke = args.scale == "smoke";
  r.rep = repro::report_input(args, repro::SmokeTargets::own_file);
  r.targets = read_json(r.rep.targets_path);
  // The tie each rotation ordering allows: its targets-file threshold.
  const harness::TargetSet target_set = harness::load_targets(r.rep.targets_path, args.repo_root);
  auto tie = [&](const char* id) { return harness::threshold(target_set, id, "tie_rtol"); };
  r.tie_stiffest = tie("ch4.trend_rotation_k0_stiffest"), r.tie_softest = tie("ch4.trend_rotation_k1_softest");
  r.tie_arrival = tie("ch4.trend_rotation_k0_earliest_arrival");
  r.tie_alpha = tie("ch4.trend_rotation_k0_closest_equilibrium");
  const auto reported = read_json(args.repo_root + "/data/digitized/chapter4/reported.json");
  auto printed = [&](const std::string& id) {
    for (const auto& v : reported.at("values"))
      if (v.at("id") == id) return v.at("value").get<double>();
    throw std::runtime_error("reported.json has no " + id);
  };
  r.limit = printed("ch4.stress_limit"), r.threshold = printed("ch4.alpha_threshold");
  r.k_cal = printed("ch4.rotational_resistance");
  set_case(r);
  // Studies beyond the printed cases (studies.json; issue 15).
  r.studies = read_json(args.set_dir() + "/studies.json");
  r.cal_set = cal_settings(r.studies);
  return r;
}

// 2. The packing (Sec. 4.3: the upscaled Song et al. PSD at porosity 0.44), timed here, through
// the cache the cases then hit. Its grain count is reported at the text's N = 2 (Table 4.1's
// count): the count scales as N^-3 for one curve shape.
void pack_specimen(Recipe& r) {
  auto& m = r.m();
  const auto t_pack0 = std::chrono::steady_clock::now();
  r.packing = harness::pack(r.set_case);
  r.pack_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_pack0).count();
  const auto& P = r.packing.result;
  std::printf("packing: %zu grains (expected %.0f), porosity %.4f, Z (no rattlers) %.2f, %s in %.1f s\n",
              P.count, P.expected_count, P.porosity, P.coordination_no_rattlers,
              r.packing.from_cache ? "from cache" : "generated", r.pack_s);
  const double to_n2 = std::pow(r.upscale / 2.0, 3);
  m.scalar("ch4.particle_count", static_cast<double>(P.count) * to_n2);
  m.note("ch4.particle_count", r.smoke ? std::to_string(P.count) + " grains at N = " + fmt("%g", r.upscale) +
                                             ", x (N/2)^3 = " + fmt("%.3f", to_n2) + " to the N = 2 equivalent"
                                       : std::to_string(P.count) + " grains at N = 2");
  m.scalar("ch4.particle_count_vs_expected", static_cast<double>(P.count) / P.expected_count);
  m.note("ch4.particle_count_vs_expected", fmt("expected V(1-n)/mean grain volume = %.0f", P.expected_count));
  m.scalar("ch4.porosity", P.porosity);
}

}  // namespace kolsky::ch4
