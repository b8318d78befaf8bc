// The thread-count rule of StepExecutor (thread_governor.hpp): windows of steps at the
// chosen count, and now and then one at the other count, adjacent in time so that both see
// the same load on the machine; the faster (by the margin) is kept.
#include "time/thread_governor.hpp"

#include <algorithm>

#include <omp.h>

namespace kolsky::time_loop {

ThreadGovernor::ThreadGovernor(int max_threads, ThreadGovernorOptions options)
    : opt_(options), max_threads_(std::max(1, max_threads)), chosen_(max_threads_) {
  opt_.window = std::max(1, opt_.window);
  opt_.first_probe = std::max(1L, opt_.first_probe);
  opt_.max_probe_interval = std::max(opt_.first_probe, opt_.max_probe_interval);
  if (opt_.start_threads >= 1 && opt_.start_threads <= max_threads_) chosen_ = opt_.start_threads;
  // interval_ = 0: the first probe follows the first window, so a loop started at the wrong
  // count leaves it within four windows (two winning probes).
}

void ThreadGovernor::record(double seconds) {
  if (max_threads_ <= 1) return;
  ++in_window_;
  window_s_ += seconds;
  if (!measuring_other_) ++since_probe_;
  if (in_window_ >= opt_.window) finish_window();
}

void ThreadGovernor::finish_window() {
  const double per_step = window_s_ / in_window_;
  in_window_ = 0;
  window_s_ = 0;
  if (!measuring_other_) {
    chosen_per_step_ = per_step;
    measuring_other_ = confirming_ || since_probe_ >= interval_;
    return;
  }
  measuring_other_ = false;
  ++probes_;
  since_probe_ = 0;
  const bool won = per_step < (1 - opt_.margin) * chosen_per_step_;
  // A probe that wins is repeated after one more window at the chosen count, and the count
  // changes only when it wins again: on a shared host one window can be slowed by 20 % or more
  // by others' work, which a single comparison would take for a change of load.
  if (won && !confirming_) {
    confirming_ = true;
    return;
  }
  confirming_ = false;
  if (won) {
    chosen_ = other();  // other() of the old choice, before chosen_ changes
    chosen_per_step_ = per_step;
    ++switches_;
    interval_ = opt_.first_probe;  // the load changed: look again soon
  } else {
    interval_ = std::clamp(2 * interval_, opt_.first_probe, opt_.max_probe_interval);
  }
}

ScopedThreads::ScopedThreads(int threads) : previous_(omp_get_max_threads()) {
  if (threads > 0 && threads != previous_) omp_set_num_threads(threads);
}

ScopedThreads::~ScopedThreads() {
  if (omp_get_max_threads() != previous_) omp_set_num_threads(previous_);
}

}  // namespace kolsky::time_loop
