// Progress bar with ETA on stderr for long runs. Silent when stderr is not a terminal or when
// disabled (--quiet), so logs and CI output stay clean.
#pragma once
#include <chrono>
#include <string>

namespace kolsky {

class Progress {
 public:
  /// total: the value at completion (e.g. end time). enabled=false makes every call a no-op.
  Progress(double total, bool enabled, std::string label = "");
  /// Redraws at most ~10 times per second.
  void update(double done);
  /// Clears the bar line.
  void finish();

 private:
  double total_;
  bool enabled_;
  std::string label_;
  std::chrono::steady_clock::time_point start_, last_;
};

/// True when stderr is an interactive terminal.
bool stderr_is_terminal();

}  // namespace kolsky
