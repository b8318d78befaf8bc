#include "chapter5/set.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>

#include "chapter5/case_json.hpp"
#include "scene/scene_change.hpp"

namespace kolsky::ch5 {

CostTable read_costs(const std::string& members_json) {
  CostTable t;
  if (!std::filesystem::exists(members_json)) return t;
  std::ifstream f(members_json);
  for (const MemberRecord& m : members_from_json(nlohmann::json::parse(f)))
    if (m.ok && !m.cached && m.wall_s > 0) t.measured[m.label] = m.wall_s;
  return t;
}

double modelled_cost(const harness::Case& c) {
  try {
    const nlohmann::json j = harness::final_scene(c);
    const auto& s = j.at("specimen");
    const double d = s.at("diameter").get<double>() * 1e3, l = s.at("length").get<double>() * 1e3;
    const double volume = std::numbers::pi / 4 * d * d * l;  // mm^3
    return volume / std::pow(s.at("upscale").get<double>(), 3) * j.at("time").at("end").get<double>() * 1e6;
  } catch (const std::exception&) {  // a scene that cannot be read fails at once: no cost
    return 1;
  }
}

std::string case_key(const CaseRunner& r, const CaseSpec& spec) {
  try {
    return scene::content_key(harness::final_scene(r.make(spec)), "chapter5 case|" + spec.label);
  } catch (const std::exception&) {  // its run fails the same way; such a member is never cached
    return "";
  }
}

namespace {

void add_member(SetEnsemble& e, ensemble::EnsembleMember m, double modelled,
                std::function<void(const ensemble::MemberResult&)> take) {
  const auto it = e.costs.measured.find(m.label);
  e.cost_measured.push_back(it != e.costs.measured.end());
  m.expected_cost = e.cost_measured.back() ? it->second : modelled;
  e.members.push_back(std::move(m));
  e.take.push_back(std::move(take));
}

}  // namespace

void add_case(SetEnsemble& e, const CaseRunner& r, const CaseSpec& spec, CaseResult* into) {
  e.planned.push_back(spec);
  double modelled = 1;
  try {
    modelled = modelled_cost(r.make(spec));
  } catch (const std::exception&) {  // the scene file cannot be read: its run says so
  }
  add_member(e, {spec.label, case_key(r, spec), 1, [r, spec] { return to_json(r.run(spec)); }}, modelled,
             [into, spec, packed = &e.packing_s](const ensemble::MemberResult& m) {
               if (m.ok) {
                 *into = case_from_json(m.value);
                 if (const auto it = packed->find(spec.label); it != packed->end())
                   into->wall_s += it->second, into->pack_s += it->second;
                 return;
               }
               *into = CaseResult{};  // the member threw (run_case itself never does)
               into->spec = spec;
               into->failure = m.error;
             });
}

void add_chain(SetEnsemble& e, const CaseRunner& r, const std::string& label, const CaseSpec& first,
               const std::string& context, double runs, std::function<nlohmann::json()> run,
               std::function<void(const nlohmann::json&)> take) {
  std::string key;
  double modelled = runs;
  try {
    const harness::Case c = r.make(first);
    key = scene::content_key(harness::final_scene(c), "chapter5 chain|" + label + "|" + context);
    modelled = runs * modelled_cost(c);
  } catch (const std::exception&) {  // never cached; its runs fail and say why
  }
  add_member(e, {label, key, 1, std::move(run)}, modelled,
             [take = std::move(take)](const ensemble::MemberResult& m) { take(m.ok ? m.value : nlohmann::json()); });
}

void run_phase(SetEnsemble& e, const std::string& phase) {
  const std::vector<ensemble::MemberResult> results = ensemble::run_ensemble(e.members, e.options);
  for (std::size_t k = 0; k < results.size(); ++k) {  // member order: the same wherever each ran
    e.take[k](results[k]);
    const auto& m = results[k];
    e.log.push_back({phase, m.label, e.members[k].expected_cost, e.cost_measured[k], m.wall_s, m.rank, m.ok,
                     m.cached, m.error});
  }
  e.members.clear();
  e.take.clear();
  e.cost_measured.clear();
  e.planned.clear();
}

void run_packings(SetEnsemble& e, const CaseRunner& r) {
  SetEnsemble kept;
  std::swap(kept.members, e.members), std::swap(kept.take, e.take), std::swap(kept.cost_measured, e.cost_measured);
  std::swap(kept.planned, e.planned);
  std::set<std::string> made;
  std::vector<std::string> owners;  // the first case of each packing
  for (const CaseSpec& spec : kept.planned) {
    harness::Case c;
    std::string key;
    try {
      c = r.make(spec);
      key = harness::packing_key(c);
    } catch (const std::exception&) {  // the case's own run says why
      continue;
    }
    if (key.empty() || !made.insert(key).second) continue;
    owners.push_back(spec.label);
    c.label = "packing for " + spec.label;
    // Not in the results cache: a rerun finds the packing in the packing cache at once.
    add_member(e, {c.label, "", 1, [c] {
                     const dem::CachedPacking p = harness::pack(c);
                     return nlohmann::json{{"grains", p.result.count}, {"from_cache", p.from_cache}};
                   }},
               modelled_cost(c), [](const ensemble::MemberResult&) {});
  }
  if (!e.members.empty()) run_phase(e, "packings");
  for (std::size_t k = 0; k < owners.size(); ++k) e.packing_s[owners[k]] = e.log[e.log.size() - owners.size() + k].wall_s;
  std::swap(kept.members, e.members), std::swap(kept.take, e.take), std::swap(kept.cost_measured, e.cost_measured);
  std::swap(kept.planned, e.planned);
}

nlohmann::json members_json(const std::vector<MemberRecord>& log) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& m : log)
    a.push_back({{"phase", m.phase}, {"label", m.label}, {"expected", m.expected}, {"expected_measured", m.measured},
                 {"wall_s", m.wall_s}, {"rank", m.rank}, {"ok", m.ok}, {"cached", m.cached}, {"error", m.error}});
  return {{"about", "reproduce_chapter5's ensemble members as they ran (reproductions/chapter5/set.hpp)"},
          {"members", a}};
}

std::vector<MemberRecord> members_from_json(const nlohmann::json& j) {
  std::vector<MemberRecord> log;
  for (const auto& m : j.at("members"))
    log.push_back({m.at("phase").get<std::string>(), m.at("label").get<std::string>(), m.value("expected", 0.0),
                   m.value("expected_measured", false), m.at("wall_s").get<double>(), m.value("rank", 0),
                   m.value("ok", true), m.value("cached", false), m.value("error", std::string())});
  return log;
}

SetSchedule model_schedule(const std::vector<MemberRecord>& log, int ranks) {
  SetSchedule s;
  s.ranks = ranks;
  std::vector<std::string> phases;
  for (const auto& m : log)
    if (std::find(phases.begin(), phases.end(), m.phase) == phases.end()) phases.push_back(m.phase);
  double total = 0;
  for (const std::string& phase : phases) {
    std::vector<double> costs;
    for (const auto& m : log)
      if (m.phase == phase) costs.push_back(m.wall_s);
    const ensemble::ScheduleModel p = ensemble::simulate_list_schedule(costs, ranks);
    s.makespan += p.makespan;
    s.critical_path += p.critical_path;
    for (double c : costs) total += c;
  }
  // Clamped: on one rank the sums of the same costs in another order differ in the last bit.
  s.idle_fraction = s.makespan > 0 ? std::max(0.0, 1 - total / (ranks * s.makespan)) : 0;
  return s;
}

std::string members_markdown(const std::vector<MemberRecord>& log, const std::string& where) {
  std::string md = "## The set as an ensemble (" + where + ")\n\n";
  md += "Each member is one case or one chain of dependent cases; phase B started when phase A had "
        "ended. Expected cost: what the scheduler ordered by (longest first): an earlier run's wall "
        "time where members.json had the member, else grains x simulated time (mm^3 x us, "
        "reproductions/chapter5/set.hpp).\n\n| phase | member | expected | wall time | rank | |\n|---|---|---|---|---|---|\n";
  double total = 0;
  for (const auto& m : log) {
    total += m.wall_s;
    md += fmt("| %s | %s | %.4g%s | %.1f s | %d | %s |\n", m.phase.c_str(), m.label.c_str(), m.expected,
              m.measured ? " s" : "", m.wall_s, m.rank,
              m.cached ? "cached" : m.ok ? "" : ("**failed**: " + m.error).c_str());
  }
  md += fmt("\nMember time summed: %.0f s. The same members on more ranks (list-scheduling model, "
            "ensemble::simulate_list_schedule, phase by phase, on these wall times):\n\n"
            "| ranks | makespan | critical path | idle |\n|---|---|---|---|\n", total);
  for (int k : {4, 8, 16, 64}) {
    const SetSchedule s = model_schedule(log, k);
    md += fmt("| %d | %.0f s | %.0f s | %.0f %% |\n", k, s.makespan, s.critical_path, 100 * s.idle_fraction);
  }
  return md + "\n";
}

}  // namespace kolsky::ch5
