// study_ringing: is the early front - back gap of the Chapter 3 1.5 x specimen the inertia of a
// specimen the rising pulse accelerates (issue 31; reproductions/chapter3/README.md, "The face
// stresses")? One case per call (resumable: a case whose summary exists is not rerun): the
// chapter3 full scene with the set's "shifted" patch, a packing seed and a pulse file of choice,
// measured by the set's own code (ch3::measure) with the ringing time at the pulse's rise end.
//   study_ringing --out DIR --label NAME [--seed K] [--pulse FILE] [--rise-end S]
// Writes DIR/NAME.json (summary) and DIR/NAME_faces.csv (t after arrival, front, back, the gap
// the specimen's momentum needs).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "chapter3/studies.hpp"
#include "io/csv.hpp"
#include "studies/study_cli.hpp"

namespace {

using namespace kolsky;

struct Options {
  std::string out, label, pulse;
  long seed = 1;
  double rise_end = 125e-6;  // the text's constant strain rate starts here (Sec. 2.3.4)
};

[[noreturn]] void usage(int code) {
  repro::exit_with_usage(code,
                         "usage: study_ringing --out DIR --label NAME [--seed K] [--pulse FILE] [--rise-end S]\n"
                         "Runs the Chapter 3 full-scale 1.5 x specimen (scene_full.json + the studies' 'shifted'\n"
                         "patch) with packing seed K (default 1) and the incident pulse FILE (default the set's;\n"
                         "an absolute path or one relative to reproductions/chapter3/), and reads the face stresses:\n"
                         "the measured gap against the specimen's momentum rate before --rise-end (default\n"
                         "125e-6 s), alpha from there to 13 MPa, alpha from the back face's 2 MPa.\n");
}

Options parse(int argc, char** argv) {
  Options o;
  repro::read_flags(argc, argv, usage, [&](const std::string& a, repro::FlagReader& r) {
    if (a == "--out") o.out = r.value();
    else if (a == "--label") o.label = r.value();
    else if (a == "--seed") o.seed = r.integer();
    else if (a == "--pulse") o.pulse = r.value();
    else if (a == "--rise-end") o.rise_end = r.number();
    else return false;
    return true;
  });
  if (o.out.empty() || o.label.empty() || !(o.rise_end > 0)) usage(1);
  if (!o.pulse.empty()) o.pulse = std::filesystem::absolute(o.pulse).string();
  return o;
}

// Largest |front - back| / mean over the samples from index a to the cut-off.
double alpha_from(const ch3::CaseResult& c, long a, long end) {
  double alpha = NAN;
  for (long k = std::max(0L, a); k < end; ++k) {
    const double x = std::abs(c.faces.front[k] - c.faces.back[k]) / (0.5 * (c.faces.front[k] + c.faces.back[k]));
    alpha = std::isnan(alpha) ? x : std::max(alpha, x);
  }
  return alpha;
}

}  // namespace

int main(int argc, char** argv) {
  repro::line_buffered_stdout();
  const Options o = parse(argc, argv);
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/reproductions/chapter3";
  const std::optional<std::string> case_stem = repro::start_case(o.out, o.label);
  if (!case_stem) return 0;
  const std::string& stem = *case_stem;
  ch3::Context x;
  x.scene_path = dir + "/scene_full.json";
  x.scene = ch3::read_json(x.scene_path);
  x.studies = ch3::read_json(dir + "/studies_full.json");
  x.packing_cache = repro::packing_cache_dir("", o.out);  // no --cache here: OUT/packing_cache
  x.ringing_time = o.rise_end;
  nlohmann::json patch;
  for (const auto& c : x.studies.at("cases"))
    if (c.at("id") == "shifted") patch = c.at("patch");
  patch["specimen"]["seed"] = o.seed;
  if (!o.pulse.empty()) patch["pulse"]["file"] = o.pulse;
  std::printf("%s: the 1.5 x specimen, seed %ld, pulse %s, rise end %.1f us\n", o.label.c_str(), o.seed,
              o.pulse.empty() ? "(the set's)" : o.pulse.c_str(), o.rise_end * 1e6);
  const ch3::CaseResult c = ch3::run_case(ch3::make_case(x, o.label, patch));
  if (!c.ok) return repro::case_failed(o.label, c.failure);
  const ch3::Measures m = ch3::measure(x, c);
  long k2 = 0;
  while (k2 < m.i_end && c.faces.back[k2] < 2e6) ++k2;
  const double alpha_2mpa = alpha_from(c, k2, m.i_end);
  const std::vector<double> need = ch3::face_inertia_gap(c, 5e-6);
  nlohmann::json j;
  j["label"] = o.label;
  j["seed"] = o.seed;
  j["pulse"] = o.pulse;
  j["rise_end_s"] = o.rise_end;
  j["grains"] = c.dem.grains;
  j["mass_per_area"] = c.mass_per_area;
  j["inertia_ratio"] = m.face_inertia_ratio;
  j["inertia_gap_max_pa"] = m.face_inertia_gap_max;
  j["alpha_from_rise_end"] = m.face_alpha_max;
  j["gap_max_from_rise_end_pa"] = m.face_gap_max;
  j["back_stress_at_rise_end_pa"] = m.stress_at_ringing_end;
  j["alpha_from_2mpa"] = alpha_2mpa;
  j["time_at_2mpa_s"] = k2 < m.i_end ? c.faces.t[k2] : NAN;
  j["time_at_13mpa_s"] = m.time_at_cutoff;
  j["wall_s"] = c.wall_s;
  std::printf("%s: %zu grains; inertia ratio %.3f (predicted gap up to %.3f MPa); alpha from the rise end %.3f "
              "(back face %.2f MPa there, largest gap after it %.3f MPa); alpha from 2 MPa %.3f; 13 MPa at %.1f us; %.0f s\n",
              o.label.c_str(), c.dem.grains, m.face_inertia_ratio, m.face_inertia_gap_max / 1e6, m.face_alpha_max,
              m.stress_at_ringing_end / 1e6, m.face_gap_max / 1e6, alpha_2mpa, m.time_at_cutoff * 1e6, c.wall_s);
  io::write_csv(stem + "_faces.csv",
                {{"t_after_arrival_s", "stress_front_pa", "stress_back_pa", "inertia_gap_pa"}, {c.faces.t, c.faces.front, c.faces.back, need}, {}, {}});
  repro::finish_case(stem, j);
  return 0;
}
