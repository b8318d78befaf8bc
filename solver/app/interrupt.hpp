// SIGINT and SIGTERM during `kolsky run`: the first signal only sets a flag, which the run
// polls at every step (and the DEM packing after every stage), so the run stops at the next
// step, writes what it computed marked incomplete, leaves no temporary file and exits with
// 128 + the signal (130, 143). The handlers reset themselves: a second signal ends the process
// at once, as an impatient user expects.
#pragma once
#include <csignal>

namespace kolsky::app {

/// Installs the handlers for its lifetime (restores the previous ones when destroyed).
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

/// The flag the run polls (shpb::RunControl::stop): non-zero once a signal arrived.
const volatile std::sig_atomic_t* interrupt_flag();
/// The signal received (SIGINT or SIGTERM), 0 if none.
int interrupt_signal();
/// "SIGINT" or "SIGTERM".
const char* interrupt_name();

}  // namespace kolsky::app
