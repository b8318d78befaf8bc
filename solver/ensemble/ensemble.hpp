// Ensembles (issue 33; docs/scale-out.md): the independent members of a reproduction set or a
// sweep, run on threads or MPI ranks, their results returned in member order so that nothing
// downstream depends on where or when each ran. A member is one case, or one chain of dependent
// cases (the steps of a calibration search run inside one member, in order). A member that
// throws is recorded with its error and the ensemble goes on. With a cache directory, a
// member's result is stored under its content key when it finishes (written atomically), and a
// restarted ensemble takes it from there instead of running the member again.
//
// Every MPI rank builds the same member list (SPMD); rank 0 hands members out, longest
// expected first, as ranks become free, and broadcasts all results at the end, so every rank
// returns the same vector. Without MPI, or on one rank, the members run on threads.
#pragma once
#include <cstddef>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace kolsky::ensemble {

struct EnsembleMember {
  std::string label;
  std::string key;            ///< content key (case_key); empty: never cached
  double expected_cost = 1;   ///< any unit (e.g. seconds measured before): the longest start first
  std::function<nlohmann::json()> run;  ///< the member's results as JSON (numbers round-trip exactly)
};

struct MemberResult {
  std::string label, key;
  bool ok = false;
  bool cached = false;        ///< read from the cache, not run
  std::string error;          ///< what a failed member threw
  double wall_s = 0;          ///< its run time (0 when cached)
  int rank = 0;               ///< where it ran (not a result: differs between runs)
  nlohmann::json value;
};

struct EnsembleOptions {
  int threads = 1;            ///< members at once on this process when not spread over ranks
  std::string cache_dir;      ///< results by key; empty: no cache
  /// Called on rank 0 after each member (in completion order), e.g. for progress and an ETA.
  std::function<void(const MemberResult&, std::size_t done, std::size_t total)> on_done;
};

/// The order members start in: expected cost descending, ties by index.
std::vector<std::size_t> schedule_order(const std::vector<EnsembleMember>& members);

/// Runs every member; result k belongs to member k, whatever ran it and in whatever order.
std::vector<MemberResult> run_ensemble(const std::vector<EnsembleMember>& members, const EnsembleOptions& options);

/// One member here and now: from the cache when its key is there, else run (exceptions caught
/// into the result) and, when it succeeded, stored. Used by every executor.
MemberResult run_member(const EnsembleMember& member, const std::string& cache_dir, int rank);

/// The MPI process layout: {0, 1} without MPI or when not started by mpirun.
struct RankLayout {
  int rank = 0, size = 1;
};
RankLayout rank_layout();

/// Initialises MPI for the program's lifetime where the build has it (a singleton without
/// mpirun), finalises it on destruction; a no-op otherwise. One per program, in main.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

/// Whether this build was made with MPI (the ensembles then spread over mpirun's ranks).
bool built_with_mpi();

/// The MPI executor (ensemble_mpi.cpp, or a stand-in that throws in a build without MPI):
/// rank 0 schedules `order` dynamically over all ranks, itself included.
std::vector<MemberResult> run_over_ranks(const std::vector<EnsembleMember>& members, const EnsembleOptions& options,
                                         const std::vector<std::size_t>& order);

/// A list-scheduling model of the ensemble on `workers` (issue 33, "Measure and model"): the
/// members' measured costs handed out longest first to the first free worker.
struct ScheduleModel {
  double makespan = 0;       ///< when the last member ends
  double critical_path = 0;  ///< the longest single member: no schedule ends sooner
  double idle_fraction = 0;  ///< 1 - total cost / (workers x makespan)
};
ScheduleModel simulate_list_schedule(const std::vector<double>& costs, int workers);

}  // namespace kolsky::ensemble
