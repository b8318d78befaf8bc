// Runs a stepper's steps on the OpenMP thread count its ThreadGovernor chooses
// (thread_governor.hpp), timing only the step's own work (issue 32: the governor in an
// executor, not in the physics). A step comes in two halves, as DemSystem's begin_step and
// finish_step, between which the caller may do other work (the bars, output) that neither
// depends on the choice nor should add its noise to the comparison. The physics inside never
// sees a thread count: it runs its OpenMP regions under the count in force, and its results
// must not depend on it (docs/dem.md, "Parallel determinism"; the choice changes speed only).
// Loops outside the halves (a bare force evaluation) use the caller's count.
#pragma once
#include <chrono>

#include "time/thread_governor.hpp"

namespace kolsky::time_loop {

class StepExecutor {
 public:
  /// adapt = false: every step at the caller's omp_get_max_threads() (benchmarks that measure
  /// a fixed count); else the governor's choice between 1 and that count, with `options`
  /// (start_threads 0: the last count any executor in the process chose).
  explicit StepExecutor(bool adapt = true, ThreadGovernorOptions options = {})
      : adapt_(adapt), options_(options) {}

  /// The first half of a step: chooses the step's count, runs work() under it and times it.
  template <class Work> void first_half(Work&& work) {
    threads_ = threads_for_step();
    const ScopedThreads scope(threads_);
    const auto t0 = Clock::now();
    work();
    first_seconds_ = seconds_since(t0);
  }
  /// The second half: runs work() under the count of the first half (the caller's if there
  /// was none) and gives the governor the step's time.
  template <class Work> void second_half(Work&& work) {
    const ScopedThreads scope(threads_);
    const auto t0 = Clock::now();
    work();
    if (threads_ > 0) record(first_seconds_ + seconds_since(t0));
    threads_ = 0;
  }

  /// The count choice (probes, switches, the count now).
  const ThreadGovernor& governor() const { return governor_; }

 private:
  using Clock = std::chrono::steady_clock;
  static double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }
  int threads_for_step();       // the governor's count (or the caller's)
  void record(double seconds);  // to the governor, when it chooses

  bool adapt_;
  ThreadGovernorOptions options_;
  // Rebuilt when the caller's count changes (threads_for_step).
  ThreadGovernor governor_{1};
  double first_seconds_ = 0;
  int threads_ = 0;  // the count the first half chose for this step (0: the caller's)
};

}  // namespace kolsky::time_loop
