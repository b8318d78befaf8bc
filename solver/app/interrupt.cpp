#include "app/interrupt.hpp"

namespace kolsky::app {

namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int sig) { g_signal = sig; }  // async-signal-safe: one store

}  // namespace

InterruptGuard::InterruptGuard() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;  // the second signal takes the default action: the process ends
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
}

const volatile std::sig_atomic_t* interrupt_flag() { return &g_signal; }
int interrupt_signal() { return g_signal; }
const char* interrupt_name() { return g_signal == SIGTERM ? "SIGTERM" : "SIGINT"; }

}  // namespace kolsky::app
