// The Chapter 5 set as an ensemble (issue 33; docs/scale-out.md): its cases and chains run as
// members of solver/ensemble's run_ensemble (threads, or MPI ranks under mpirun, rank 0 handing
// out the longest expected first), in two phases: A, the independent cases; B, the chains that
// need A's results (a back-calculation's evaluations are one member, run in order). After a
// phase every result goes to its place in member order, so what the studies measure does not
// depend on where or when a member ran. Each member's run time is logged (members.json, the
// report) with its expected cost, and the log feeds a list-scheduling model of the set on more
// ranks (ensemble::simulate_list_schedule).
#pragma once
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "chapter5/ch5.hpp"
#include "ensemble/ensemble.hpp"

namespace kolsky::ch5 {

/// One member as it ran.
struct MemberRecord {
  std::string phase, label;
  double expected = 0;        ///< the scheduler's expected cost (s when measured, else the model's unit)
  bool measured = false;      ///< expected is an earlier run's wall time
  double wall_s = 0;          ///< 0 when taken from the result cache
  int rank = 0;
  bool ok = false, cached = false;
  std::string error;
};

/// Expected costs: a member's wall time in an earlier run's members.json where it names the
/// member, else modelled_cost.
struct CostTable {
  std::map<std::string, double> measured;  ///< label -> s
};
CostTable read_costs(const std::string& members_json);  ///< empty when the file is not there

/// The model: grains x simulated time, in mm^3 x us: the specimen's volume / N^3 for the
/// grains (one sand, upscaled) and time.end for the simulated time (a run that ends at a
/// stress is counted to time.end). 1 where the case's scene cannot be read.
double modelled_cost(const harness::Case& c);

struct SetEnsemble {
  ensemble::EnsembleOptions options;
  CostTable costs;
  std::vector<ensemble::EnsembleMember> members;  ///< the phase being planned
  std::vector<std::function<void(const ensemble::MemberResult&)>> take;  ///< where each result goes
  std::vector<bool> cost_measured;
  std::vector<CaseSpec> planned;  ///< the cases among the planned members (run_packings)
  /// Case label -> seconds its packing took in the packings phase: the first planned case of
  /// each packing pays for it (wall_s and pack_s), as it did when it packed for itself.
  std::map<std::string, double> packing_s;
  std::vector<MemberRecord> log;  ///< every member run so far, phase by phase
};

/// A case as a member of the phase being planned; its record goes to *into after the phase.
/// Its key: the final scene with the label (ensemble cache).
void add_case(SetEnsemble& e, const CaseRunner& r, const CaseSpec& spec, CaseResult* into);

/// A chain as a member: `run` runs its dependent cases in order, its JSON goes to `take` after
/// the phase (a member that threw: `take` gets null). `first` is its first case: the key is
/// its final scene with `context` (what else decides the chain: settings, reference's key),
/// the modelled cost that case's times `runs`.
void add_chain(SetEnsemble& e, const CaseRunner& r, const std::string& label, const CaseSpec& first,
               const std::string& context, double runs, std::function<nlohmann::json()> run,
               std::function<void(const nlohmann::json&)> take);

/// The member key of a case (scene::content_key of its final scene and its label): chains name
/// their reference by it. "" when its scene cannot be read.
std::string case_key(const CaseRunner& r, const CaseSpec& spec);

/// Runs the planned members, hands each result to its place in member order, logs them under
/// `phase`, and clears the plan for the next phase.
void run_phase(SetEnsemble& e, const std::string& phase);

/// Before the planned phase runs: each distinct packing of its cases made once, as a member of
/// a phase of its own ("packings"), so that cases sharing a packing (the pair and the variants;
/// the reference and its companion) do not each make it at once; they then read it from the
/// packing cache, bitwise as made (dem/packing_cache.hpp). The planned phase is kept.
void run_packings(SetEnsemble& e, const CaseRunner& r);

/// The log as members.json (what read_costs reads back).
nlohmann::json members_json(const std::vector<MemberRecord>& log);
std::vector<MemberRecord> members_from_json(const nlohmann::json& j);

/// The list-scheduling model of the logged members on `ranks`: phase by phase (B starts when A
/// has ended), each phase's members longest first to the first free rank.
struct SetSchedule {
  int ranks = 0;
  double makespan = 0;       ///< s: the phases' makespans summed
  double critical_path = 0;  ///< s: the phases' longest members summed (no schedule ends sooner)
  double idle_fraction = 0;  ///< 1 - total member time / (ranks x makespan)
};
SetSchedule model_schedule(const std::vector<MemberRecord>& log, int ranks);

/// The report's section: every member (phase, expected cost, wall time, rank) and the model on
/// 4, 8, 16 and 64 ranks.
std::string members_markdown(const std::vector<MemberRecord>& log, const std::string& where);

}  // namespace kolsky::ch5
