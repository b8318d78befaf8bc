// Running a sweep's members (sweep_plan.hpp) through the ensemble executor: each member is its
// scene built and run as `kolsky run` would, analysed, and reduced to the summary figures
// `kolsky run` prints (shpb/summary.hpp), its step count and its run time. Members are keyed by
// content (scene/scene_change.hpp: the final scene, the binary, the scene's folder) and cached
// on disk by the ensemble, so a sweep killed half-way resumes where it stopped.
//
// A member the solver refuses when it builds it (a time step above a stiffer member's stable
// limit) or one that blows up is a result, status "failed" with its error; both are what the
// scene decides, so they are cached like a success. A member stopped by a signal or one that
// threw anything else is not cached: the ensemble records its error and a rerun runs it again.
#pragma once
#include <csignal>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ensemble/ensemble.hpp"
#include "sweep/sweep_plan.hpp"

namespace kolsky::sweep {

struct MemberOptions {
  int omp_threads = 0;  ///< OpenMP threads of each member (0: the default); results do not depend on it
  /// Polled before every step (a signal handler's flag): a member stopped so throws StopRequested.
  const volatile std::sig_atomic_t* stop = nullptr;
};

/// What a member's run gives, as the ensemble carries and caches it:
///   {"status": "ok" | "failed", "failure_kind": "" | "numerical" | "input", "error": "...",
///    "summary": {...}, "steps": n, "ended_by": "...", "run_s": s}
/// `file` names the scene in errors; relative paths in it resolve against `base_dir`.
nlohmann::json run_scene(const nlohmann::json& scene, const std::string& file, const std::string& base_dir,
                         const MemberOptions& options);

/// The content key of a member: scene::content_key of its scene with the scene's folder.
std::string member_key(const SweepPlan& plan, const SweepPoint& point);

/// One ensemble member per point, in point order (expected cost 1 each: the executor starts
/// them in this order).
std::vector<ensemble::EnsembleMember> sweep_members(const SweepPlan& plan, const std::vector<SweepPoint>& points,
                                                    const MemberOptions& options);

/// A member's outcome as the table writes it (ensemble result and run value together).
struct MemberOutcome {
  bool ok = false;              ///< ran to the end and analysed
  std::string failure_kind;     ///< "numerical", "input", "error" (threw), "" when ok
  std::string error;
  double run_s = 0;             ///< the member's own run time (as first run, when cached)
  bool cached = false;
};
MemberOutcome outcome(const ensemble::MemberResult& r);

/// Seconds left, estimated from the members run so far (cached ones cost nothing): elapsed /
/// run x remaining; negative when nothing has run yet (no estimate).
double eta_seconds(double elapsed_s, std::size_t run, std::size_t remaining);

/// "kolsky sweep: 3/10 done (key=1 seed=2: ok, 1.23 s), elapsed 4.1 s, about 9.6 s left".
std::string progress_line(const ensemble::MemberResult& r, std::size_t done, std::size_t total,
                          double elapsed_s, std::size_t run);

}  // namespace kolsky::sweep
