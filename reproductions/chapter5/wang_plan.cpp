// Wang et al. (2018), Sec. 5.3.1 and 5.3.4, what runs: the original and the 1.5x specimen with
// their own sigma_lim0, the breakage-criterion variants (Fig. 5.8), the twin experiment and the
// back-calculations of sigma_lim0(N) (Fig. 5.16), speed against error of N, and the companions
// of the known deviations; as the set's ensemble members (set.hpp). What is measured on them:
// wang.cpp.
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "chapter5/case_json.hpp"
#include "chapter5/studies.hpp"
#include "dem/breakage_model.hpp"

namespace kolsky::ch5 {

namespace {

/// Every Wang case: the scene at N with sigma_lim0, the fines' d_min, the cases file's end (or,
/// loaded until a stress, its loading, stress and end).
CaseSpec wang_spec(const Study& s, const std::string& label, double n, double sigma) {
  const auto& w = s.cases.at("wang");
  CaseSpec c;
  c.label = label;
  c.scene = "scene_wang.json";
  c.upscale = n;
  c.sigma_lim0 = sigma;
  c.end_time = w.at("end_time").get<double>();
  c.fines_d_min = s.printed("ch5.wang.fines_d_min");
  if (w.contains("load_until")) {
    const auto& u = w.at("load_until");
    c.loading_file = u.at("loading_file").get<std::string>();
    c.end_at_back_stress = u.at("back_stress").get<double>();
    c.end_time = u.at("end_time").get<double>();
  }
  return c;
}

/// Fig. 5.8's comparison at equal strain: the scene's own loading history.
CaseSpec with_scene_history(CaseSpec c, double end) {
  c.loading_file.clear();
  c.end_at_back_stress = -1;
  c.end_time = end;
  return c;
}

void plan_chains(const Study& s, WangPlan& p) {
  const auto& w = s.cases.at("wang");
  const int cap = w.at("backcalc_max_evaluations").get<int>();
  const double factor = w.at("backcalc_bracket_factor").get<double>();
  // Twin experiment of the back-calculation: the twin's own curve, made with a known
  // sigma_lim0, must be recovered from a start guess_factor away (the objective is 0 there: the
  // runs are deterministic), before the procedure is trusted against another N.
  p.has_twin = w.contains("twin_guess_factor");
  if (p.has_twin) {
    p.twin.n = p.n_twin;
    p.twin.settings.guess = p.sig_twin * w.at("twin_guess_factor").get<double>();
    p.twin.settings.factor = factor;
    p.twin.settings.max_evaluations = cap;
    p.twin.candidate = wang_spec(s, fmt("twin N = %g", p.n_twin), p.n_twin, p.twin.settings.guess);
  }
  // Back-calculation (Sec. 5.3.4) against the reference curve, at each backcalc_n.
  for (const auto& jn : w.at("backcalc_n")) {
    BackCalcPlan b;
    b.n = jn.get<double>();
    b.settings.guess = dem::sigma_lim0_between(p.sig_ref, p.n_ref, b.n, p.m1);
    b.settings.factor = factor;
    b.settings.max_evaluations = cap;
    b.settings.stress_lo = 1e6;
    b.candidate = wang_spec(s, fmt("Wang N = %g (back-calculation)", b.n), b.n, b.settings.guess);
    p.backcalcs.push_back(b);
  }
  // Speed against error: every N with its back-calculated sigma (Eq. 5.17's where none), and
  // the packing seeds of speed_seeds from speed_seeds_from_n up: at N = 1.5 two more packings
  // and runs cost ~7 min of the two cores (README, "Speed against error").
  const std::vector<long> seeds = w.value("speed_seeds", std::vector<long>{});
  const double seeds_from_n = w.value("speed_seeds_from_n", 0.0);
  for (const auto& jn : w.at("speed_n")) {
    SpeedPlan sp;
    sp.n = jn.get<double>();
    sp.is_ref = std::abs(sp.n - p.n_ref) < 1e-12;
    for (std::size_t k = 0; k < p.backcalcs.size() && sp.backcalc < 0; ++k)
      if (std::abs(p.backcalcs[k].n - sp.n) < 1e-12) sp.backcalc = static_cast<long>(k);
    sp.eq517 = wang_spec(s, fmt("Wang N = %g (Eq. 5.17)", sp.n), sp.n, dem::sigma_lim0_between(p.sig_ref, p.n_ref, sp.n, p.m1));
    if (!sp.is_ref && sp.n >= seeds_from_n) sp.seeds = seeds;
    p.speed.push_back(sp);
  }
}

}  // namespace

WangPlan wang_plan(const Study& s) {
  const auto& w = s.cases.at("wang");
  WangPlan p;
  p.n_ref = w.at("n_reference").get<double>(), p.n_pair = w.at("n_pair").get<double>();
  p.sig1 = s.printed("ch5.wang.sigma_lim0_n1"), p.sig15 = s.printed("ch5.wang.sigma_lim0_n1_5");
  p.end = w.at("end_time").get<double>();
  p.pair_low_rms = s.threshold("ch5.wang.pair_coincide_low", "max_rms_pa");
  p.pair_high_frac = s.threshold("ch5.wang.pair_close_high", "max_rms_fraction_of_top");
  p.variants_rms = s.threshold("ch5.wang.variants_coincide_low", "max_rms_pa");
  p.nobreak_ratio = s.threshold("ch5.wang.nobreak_stiffer_high", "min_stress_ratio");
  p.clim0_ratio = s.threshold("ch5.wang.clim0_much_softer", "max_stress_ratio");
  p.clim0_breaks = s.threshold("ch5.wang.clim0_breaks_more", "min_broken_ratio");
  // The text's sigma_lim0 at N = 1 and 1.5. In general the reference N carries Eq. 5.17's value
  // sigma(1) N and the pair Eq. 5.17 times the text's own departure from it, 2.37 / 2.295:
  // exactly the text's two values at N = 1 and 1.5.
  p.m1 = scene_m1(s.dir, "scene_wang.json");
  p.sig_ref = dem::sigma_lim0_between(p.sig1, 1.0, p.n_ref, p.m1);
  p.sig_pair = dem::upscaled_sigma_lim0(p.sig_ref, p.n_pair / p.n_ref, p.m1) * p.sig15 /
               dem::upscaled_sigma_lim0(p.sig1, 1.5, p.m1);
  // Loaded until a stress (issue 31, H2; README "H2 and H3"): with "load_until" in the cases
  // file the runs hold the peak rate and end once the back stress reaches it (the text compares
  // the pair at 72 MPa), within until_end_time; the variants of Fig. 5.8 keep the scene's history.
  p.until = w.contains("load_until");
  p.ref = wang_spec(s, fmt("Wang N = %g", p.n_ref), p.n_ref, p.sig_ref);
  p.pair = wang_spec(s, fmt("Wang N = %g", p.n_pair), p.n_pair, p.sig_pair);
  // The twin experiment runs at twin_n (default: the pair's N, whose run is then the synthetic curve).
  p.n_twin = w.value("twin_n", p.n_pair);
  p.twin_is_pair = std::abs(p.n_twin - p.n_pair) < 1e-12;
  p.sig_twin = p.twin_is_pair ? p.sig_pair : dem::sigma_lim0_between(p.sig_ref, p.n_ref, p.n_twin, p.m1);
  if (!p.twin_is_pair) p.twin_ref = wang_spec(s, fmt("twin N = %g (synthetic curve)", p.n_twin), p.n_twin, p.sig_twin);
  // The breakage-criterion variants (Fig. 5.8), at the same sigma_lim0, at variants_n; loaded
  // until a stress, the pair ran another history: the variants' base reruns the scene's.
  p.nv = w.at("variants_n").get<double>();
  p.sig_v = (std::abs(p.nv - p.n_pair) < 1e-12 ? p.pair : p.ref).sigma_lim0;
  if (p.until) p.base_rerun = with_scene_history(wang_spec(s, fmt("Wang N = %g, c_lim = 8 (Fig. 5.8 history)", p.nv), p.nv, p.sig_v), p.end);
  p.nobreak = with_scene_history(wang_spec(s, fmt("Wang N = %g, no breakage", p.nv), p.nv, p.sig_v), p.end);
  p.nobreak.breakage = false;
  p.clim0 = with_scene_history(wang_spec(s, fmt("Wang N = %g, c_lim = 0", p.nv), p.nv, p.sig_v), p.end);
  p.clim0.coordination_limit = 0;
  // The companions of the known deviations (issue 31): full scale only (cases "companions").
  p.has_companions = w.contains("companions");
  if (p.has_companions) {
    const auto& e = w.at("companions").at("end_count");
    p.end_count = p.pair;  // the pair as the set runs it, loaded on to the text's final count
    p.end_count.label = fmt("Wang N = %g, loaded on to the text's final count", p.n_pair);
    p.end_count.end_at_back_stress = e.at("back_stress").get<double>();
    p.end_count.end_time = e.at("end_time").get<double>();
    p.ref_nobreak = with_scene_history(wang_spec(s, fmt("Wang N = %g, no breakage", p.n_ref), p.n_ref, p.sig_ref), p.end);
    p.ref_nobreak.breakage = false;
  }
  plan_chains(s, p);
  return p;
}

const CaseResult& WangRuns::base(const WangPlan& p) const {
  return p.until ? base_rerun : std::abs(p.nv - p.n_pair) < 1e-12 ? pair : ref;
}

void wang_cases(const WangPlan& p, const CaseRunner& r, SetEnsemble& e, WangRuns& runs) {
  add_case(e, r, p.ref, &runs.ref);
  add_case(e, r, p.pair, &runs.pair);
  if (!p.twin_is_pair) add_case(e, r, p.twin_ref, &runs.twin_ref);
  if (p.until) add_case(e, r, p.base_rerun, &runs.base_rerun);
  add_case(e, r, p.nobreak, &runs.nobreak);
  add_case(e, r, p.clim0, &runs.clim0);
  // The first three evaluations of each back-calculation do not depend on the curve they are
  // scored against, so they run here, beside the reference and on other ranks, instead of one
  // after another at the head of their chain (issue 33); the chain takes them back (add_backcalc).
  const auto add_first = [&](const BackCalcPlan& b, const std::string& what, std::array<CaseResult, 3>& into) {
    const std::array<double, 3> sigma = first_evaluations(b.settings);
    for (std::size_t i = 0; i < sigma.size(); ++i) {
      CaseSpec c = b.candidate;
      c.sigma_lim0 = sigma[i];
      c.label = fmt("%s: sigma_lim0 %.4g GPa (first bracket)", what.c_str(), sigma[i] / 1e9);
      add_case(e, r, c, &into[i]);
    }
  };
  runs.backcalc_first.resize(p.backcalcs.size());  // before add_case keeps pointers into it
  if (p.has_twin) add_first(p.twin, fmt("twin experiment at N = %g", p.n_twin), runs.twin_first);
  for (std::size_t k = 0; k < p.backcalcs.size(); ++k)
    add_first(p.backcalcs[k], fmt("back-calculation at N = %g", p.backcalcs[k].n), runs.backcalc_first[k]);
}

namespace {

/// One N of speed against error after its back-calculation (done: its result, or none): the
/// run (the best run where it is good, else one at Eq. 5.17's sigma_lim0), then its packing
/// seeds at that run's sigma_lim0 (each packs afresh), each kept when it ran.
std::vector<CaseResult> speed_runs(const SpeedPlan& sp, const CaseRunner& r, const BackCalcResult* done) {
  std::vector<CaseResult> out{done != nullptr && done->best.ok ? done->best : r.run(sp.eq517)};
  if (!out.front().ok) return out;
  for (long seed : sp.seeds) {
    CaseSpec c = sp.eq517;
    c.label = fmt("Wang N = %g (seed %ld)", sp.n, seed);
    c.sigma_lim0 = out.front().spec.sigma_lim0;
    c.seed = seed;
    if (CaseResult run = r.run(c); run.ok) out.push_back(std::move(run));
  }
  return out;
}

nlohmann::json cases_json(const std::vector<CaseResult>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& c : v) a.push_back(to_json(c));
  return a;
}

std::vector<CaseResult> cases_from_json(const nlohmann::json& a) {
  std::vector<CaseResult> v;
  if (a.is_array())
    for (const auto& c : a) v.push_back(case_from_json(c));
  return v;
}

std::string context(const BackCalcPlan& b, const std::string& reference_key, const SpeedPlan* sp) {
  const BackCalcSettings& s = b.settings;
  nlohmann::json j = {{"settings", {s.guess, s.factor, s.rel_tol, s.max_evaluations, s.stress_lo, s.stress_hi}},
                      {"reference", reference_key}};
  if (sp != nullptr) j["speed"] = {to_json(sp->eq517), sp->seeds};
  return j.dump();
}

/// A back-calculation as one chain member: its evaluations in order against `reference`, then
/// (speed set) that N's speed runs. Its results go to *into and *speed_into. `first`: its first
/// three evaluations, run in phase A (wang_cases); the chain takes each back as the search asks
/// for it (the same sigma_lim0 bit for bit, so the search and its result are those of a chain
/// that runs them itself).
void add_backcalc(SetEnsemble& e, const CaseRunner& r, const std::string& label, const BackCalcPlan& b,
                  const std::array<CaseResult, 3>& first, const CaseResult& reference,
                  const std::string& reference_key, const SpeedPlan* speed, BackCalcResult* into,
                  std::vector<CaseResult>* speed_into) {
  std::optional<SpeedPlan> sp;
  if (speed != nullptr) sp = *speed;
  auto run = [r, b, first, reference, sp] {
    auto evaluate = [&](double sigma) {
      for (const CaseResult& f : first)
        if (f.spec.sigma_lim0 == sigma) {
          CaseResult c = f;
          c.spec.label = b.candidate.label;  // the record the chain's own run would have made
          return c;
        }
      CaseSpec c = b.candidate;
      c.sigma_lim0 = sigma;
      return r.run(c);
    };
    const BackCalcResult done = back_calculate(evaluate, reference, b.settings);
    nlohmann::json j = {{"backcalc", to_json(done)}};
    if (sp) j["speed"] = cases_json(speed_runs(*sp, r, &done));
    return j;
  };
  auto take = [into, speed_into](const nlohmann::json& j) {
    *into = j.is_null() ? BackCalcResult{} : backcalc_from_json(j.at("backcalc"));
    if (speed_into != nullptr && !j.is_null()) *speed_into = cases_from_json(j.value("speed", nlohmann::json()));
  };
  add_chain(e, r, label, b.candidate, context(b, reference_key, speed), b.settings.max_evaluations + (sp ? 1.0 + sp->seeds.size() : 0.0),
            run, take);
}

}  // namespace

void wang_chains(const WangPlan& p, const CaseRunner& r, SetEnsemble& e, WangRuns& runs) {
  const CaseResult& truth = p.twin_is_pair ? runs.pair : runs.twin_ref;
  if (truth.ok && p.has_twin) {
    runs.twin_ran = true;
    add_backcalc(e, r, fmt("twin experiment at N = %g", p.n_twin), p.twin, runs.twin_first, truth,
                 case_key(r, p.twin_is_pair ? p.pair : p.twin_ref), nullptr, &runs.twin, nullptr);
  }
  if (runs.ref.ok) {  // the back-calculations and speed against error need the reference
    runs.backcalcs.resize(p.backcalcs.size());
    runs.speed.resize(p.speed.size());
    const std::string ref_key = case_key(r, p.ref);
    for (std::size_t k = 0; k < p.backcalcs.size(); ++k) {
      long speed = -1;  // the first non-reference N of speed against error that takes its best run
      for (std::size_t i = 0; i < p.speed.size() && speed < 0; ++i)
        if (!p.speed[i].is_ref && p.speed[i].backcalc == static_cast<long>(k)) speed = static_cast<long>(i);
      add_backcalc(e, r, fmt("back-calculation at N = %g%s", p.backcalcs[k].n, speed >= 0 ? ", then its speed runs" : ""),
                   p.backcalcs[k], runs.backcalc_first[k], runs.ref, ref_key, speed >= 0 ? &p.speed[speed] : nullptr, &runs.backcalcs[k],
                   speed >= 0 ? &runs.speed[speed] : nullptr);
    }
    for (std::size_t i = 0; i < p.speed.size(); ++i) {
      const SpeedPlan& sp = p.speed[i];
      if (sp.is_ref) runs.speed[i] = {runs.ref};
      if (sp.is_ref || sp.backcalc >= 0) continue;
      add_chain(e, r, fmt("speed at N = %g", sp.n), sp.eq517, nlohmann::json(sp.seeds).dump(), 1.0 + sp.seeds.size(),
                [sp, r] { return cases_json(speed_runs(sp, r, nullptr)); },
                [into = &runs.speed[i]](const nlohmann::json& j) { *into = cases_from_json(j); });
    }
  }
  // The companions of the known deviations, when every run they compare with ran.
  if (p.has_companions && runs.ref.ok && runs.base(p).ok && runs.nobreak.ok && runs.clim0.ok) {
    add_case(e, r, p.end_count, &runs.end_count);
    add_case(e, r, p.ref_nobreak, &runs.ref_nobreak);
  }
}

}  // namespace kolsky::ch5
