// How many OpenMP threads a stepping loop uses, chosen from the step rate it measures (issue 18;
// the rule of StepExecutor, step_executor.hpp, which DemSystem's steps run through).
//
// Why: with one of two cores held by another process, two threads are slower than one under
// every OpenMP wait policy (pack_35k, 2026-12-02: one thread 10.6 M particle-steps/s; two
// threads 4.0 M with libgomp's default spin, 3.7-6.5 M with GOMP_SPINCOUNT 1e5-3e3, 7.2 M with
// OMP_WAIT_POLICY=passive), because every barrier waits for the thread that shares its core,
// while on an idle machine the default spin is the fastest policy (14.0 M against 10.6-12.4 M).
// A wait policy cannot have both, and libgomp reads it once, when it is loaded. So the loop
// keeps the default and measures instead: it runs a window of steps with the other thread
// count now and then and keeps whichever was faster (twice in a row, so one window slowed by
// the host's noise does not decide). DemSystem's results are bitwise the same
// for any thread count (docs/dem.md, "Parallel determinism"), so the choice changes the speed
// only, never a result.
//
// A value type fed with the wall time of each step; the clock is the caller's, so the rule is
// tested with made-up timings (verification/test_thread_governor.cpp).
#pragma once

namespace kolsky::time_loop {

struct ThreadGovernorOptions {
  int window = 64;                  ///< steps per measurement (several list rebuilds), > 0
  long first_probe = 1024;          ///< steps at the chosen count before the next probe, > 0
  long max_probe_interval = 16384;  ///< the interval doubles after each probe that loses
  double margin = 0.05;             ///< the other count must be this much faster to be chosen
  /// The count to start from (1 ... max_threads; 0 or out of range: max_threads). StepExecutor
  /// passes the last choice of any governor in the process: the load on the machine outlives
  /// one system (a packing's growth, settling and pre-stress, then the test, each have one).
  int start_threads = 0;
};

class ThreadGovernor {
 public:
  /// Chooses between 1 and `max_threads` threads (max_threads <= 1: always 1, no probing),
  /// starting from options.start_threads.
  explicit ThreadGovernor(int max_threads, ThreadGovernorOptions options = {});

  /// Threads for the next step.
  int threads() const { return measuring_other_ ? other() : chosen_; }
  /// The wall time of the step just taken with threads(), s.
  void record(double seconds);

  int max_threads() const { return max_threads_; }
  long switches() const { return switches_; }  ///< times the chosen count changed
  long probes() const { return probes_; }      ///< windows run with the other count

 private:
  int other() const { return chosen_ == 1 ? max_threads_ : 1; }
  void finish_window();

  ThreadGovernorOptions opt_;
  int max_threads_ = 1;
  int chosen_ = 1;
  bool measuring_other_ = false;
  bool confirming_ = false;       // the last probe won; the next one decides
  long since_probe_ = 0;          // steps at the chosen count since the last probe
  long interval_ = 0;             // steps between probes
  int in_window_ = 0;             // steps of the current window so far
  double window_s_ = 0;           // their wall time
  double chosen_per_step_ = 0;    // the last full window at the chosen count, s per step
  long switches_ = 0, probes_ = 0;
};

/// OpenMP's thread count for the parallel regions opened in its scope (threads <= 0: the
/// caller's, unchanged); the caller's count is restored at its end, so code outside the
/// executed step (FE bars, I/O) is not affected.
class ScopedThreads {
 public:
  explicit ScopedThreads(int threads);
  ~ScopedThreads();
  ScopedThreads(const ScopedThreads&) = delete;
  ScopedThreads& operator=(const ScopedThreads&) = delete;

 private:
  int previous_;
};

}  // namespace kolsky::time_loop
