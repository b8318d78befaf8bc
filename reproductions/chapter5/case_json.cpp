#include "chapter5/case_json.hpp"

#include <cmath>
#include <string>

namespace kolsky::ch5 {

namespace {

using nlohmann::json;

// JSON has no NaN or infinity: they travel as strings, everything else as a number.
json number(double v) {
  if (std::isfinite(v)) return v;
  if (std::isnan(v)) return std::signbit(v) ? "-nan" : "nan";
  return v > 0 ? "inf" : "-inf";
}

double number(const json& j) {
  if (j.is_number()) return j.get<double>();
  const std::string s = j.get<std::string>();
  if (s == "nan" || s == "-nan") return std::copysign(NAN, s == "nan" ? 1.0 : -1.0);
  return s == "inf" ? INFINITY : -INFINITY;
}

json numbers(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(number(x));
  return a;
}

std::vector<double> numbers(const json& a) {
  std::vector<double> v;
  v.reserve(a.size());
  for (const auto& x : a) v.push_back(number(x));
  return v;
}

}  // namespace

json to_json(const CaseSpec& s) {
  return {{"label", s.label},
          {"scene", s.scene},
          {"upscale", number(s.upscale)},
          {"sigma_lim0", number(s.sigma_lim0)},
          {"coordination_limit", s.coordination_limit},
          {"breakage", s.breakage},
          {"end_time", number(s.end_time)},
          {"fines_d_min", number(s.fines_d_min)},
          {"loading_file", s.loading_file},
          {"end_at_back_stress", number(s.end_at_back_stress)},
          {"seed", s.seed},
          {"sets", s.sets}};
}

CaseSpec spec_from_json(const json& j) {
  CaseSpec s;
  s.label = j.at("label").get<std::string>();
  s.scene = j.at("scene").get<std::string>();
  s.upscale = number(j.at("upscale"));
  s.sigma_lim0 = number(j.at("sigma_lim0"));
  s.coordination_limit = j.at("coordination_limit").get<int>();
  s.breakage = j.at("breakage").get<bool>();
  s.end_time = number(j.at("end_time"));
  s.fines_d_min = number(j.at("fines_d_min"));
  s.loading_file = j.at("loading_file").get<std::string>();
  s.end_at_back_stress = number(j.at("end_at_back_stress"));
  s.seed = j.at("seed").get<long>();
  s.sets = j.at("sets").get<std::vector<std::string>>();
  return s;
}

json to_json(const CaseResult& c) {
  json curves = json::array();
  for (const auto& g : c.curves)
    curves.push_back({{"t", number(g.t)}, {"diameter", numbers(g.curve.diameter)},
                      {"percent_passing", numbers(g.curve.percent_passing)}});
  return {{"spec", to_json(c.spec)},
          {"ok", c.ok},
          {"failure", c.failure},
          {"upscale", number(c.upscale)},
          {"wall_s", number(c.wall_s)},
          {"pack_s", number(c.pack_s)},
          {"dt", number(c.dt)},
          {"simulated_s", number(c.simulated_s)},
          {"dt_final", number(c.dt_final)},
          {"steps", c.steps},
          {"grains_initial", c.grains_initial},
          {"grains_final", c.grains_final},
          {"t", numbers(c.t)},
          {"strain", numbers(c.strain)},
          {"stress_back", numbers(c.stress_back)},
          {"stress_avg", numbers(c.stress_avg)},
          {"grain_count", numbers(c.grain_count)},
          {"broken_primary", numbers(c.broken_primary)},
          {"broken_secondary", numbers(c.broken_secondary)},
          {"relative_breakage", numbers(c.relative_breakage)},
          {"held_primary", numbers(c.held_primary)},
          {"held_primary_at_limit", numbers(c.held_primary_at_limit)},
          {"curves", curves},
          {"gauges", {{"t", numbers(c.gauges.t)}, {"incident", numbers(c.gauges.incident)},
                      {"transmission", numbers(c.gauges.transmission)}}},
          {"arrival_time", number(c.arrival_time)},
          {"coordination_final", number(c.coordination_final)},
          {"ended_by", c.ended_by}};
}

CaseResult case_from_json(const json& j) {
  CaseResult c;
  c.spec = spec_from_json(j.at("spec"));
  c.ok = j.at("ok").get<bool>();
  c.failure = j.at("failure").get<std::string>();
  c.upscale = number(j.at("upscale"));
  c.wall_s = number(j.at("wall_s"));
  c.pack_s = number(j.at("pack_s"));
  c.dt = number(j.at("dt"));
  c.simulated_s = number(j.at("simulated_s"));
  c.dt_final = number(j.at("dt_final"));
  c.steps = j.at("steps").get<long>();
  c.grains_initial = j.at("grains_initial").get<std::size_t>();
  c.grains_final = j.at("grains_final").get<std::size_t>();
  c.t = numbers(j.at("t"));
  c.strain = numbers(j.at("strain"));
  c.stress_back = numbers(j.at("stress_back"));
  c.stress_avg = numbers(j.at("stress_avg"));
  c.grain_count = numbers(j.at("grain_count"));
  c.broken_primary = numbers(j.at("broken_primary"));
  c.broken_secondary = numbers(j.at("broken_secondary"));
  c.relative_breakage = numbers(j.at("relative_breakage"));
  c.held_primary = numbers(j.at("held_primary"));
  c.held_primary_at_limit = numbers(j.at("held_primary_at_limit"));
  for (const auto& g : j.at("curves"))
    c.curves.push_back({number(g.at("t")), {numbers(g.at("diameter")), numbers(g.at("percent_passing"))}});
  const json& g = j.at("gauges");
  c.gauges = {numbers(g.at("t")), numbers(g.at("incident")), numbers(g.at("transmission"))};
  c.arrival_time = number(j.at("arrival_time"));
  c.coordination_final = number(j.at("coordination_final"));
  c.ended_by = j.at("ended_by").get<std::string>();
  return c;
}

json to_json(const BackCalcResult& r) {
  json evaluated = json::array();
  for (const auto& [sigma, score] : r.evaluated) evaluated.push_back({number(sigma), number(score)});
  return {{"sigma", number(r.sigma)},           {"score", number(r.score)},
          {"bracket_lo", number(r.bracket_lo)}, {"bracket_hi", number(r.bracket_hi)},
          {"converged", r.converged},           {"evaluated", evaluated},
          {"best", to_json(r.best)},            {"note", r.note}};
}

BackCalcResult backcalc_from_json(const json& j) {
  BackCalcResult r;
  r.sigma = number(j.at("sigma"));
  r.score = number(j.at("score"));
  r.bracket_lo = number(j.at("bracket_lo"));
  r.bracket_hi = number(j.at("bracket_hi"));
  r.converged = j.at("converged").get<bool>();
  for (const auto& e : j.at("evaluated")) r.evaluated[number(e.at(0))] = number(e.at(1));
  r.best = case_from_json(j.at("best"));
  r.note = j.at("note").get<std::string>();
  return r;
}

}  // namespace kolsky::ch5
