// StepExecutor (step_executor.hpp): which count a step runs on, and the governor's record.
#include "time/step_executor.hpp"

#include <atomic>

#include <omp.h>

namespace kolsky::time_loop {

namespace {

// The last count chosen by any executor's governor in this process (0: none yet), the start of
// the next governor (ThreadGovernorOptions::start_threads). Only the speed depends on it.
std::atomic<int> g_last_step_threads{0};

}  // namespace

int StepExecutor::threads_for_step() {
  const int cap = omp_get_max_threads();
  if (!adapt_ || cap <= 1) return cap;
  if (governor_.max_threads() != cap) {
    ThreadGovernorOptions o = options_;
    if (o.start_threads == 0) o.start_threads = g_last_step_threads.load(std::memory_order_relaxed);
    governor_ = ThreadGovernor(cap, o);
  }
  return governor_.threads();
}

void StepExecutor::record(double seconds) {
  if (!adapt_ || governor_.max_threads() <= 1) return;
  const long switches = governor_.switches();
  governor_.record(seconds);
  if (governor_.switches() != switches)
    g_last_step_threads.store(governor_.threads(), std::memory_order_relaxed);
}

}  // namespace kolsky::time_loop
