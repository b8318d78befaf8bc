#include "core/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace kolsky {

bool stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

Progress::Progress(double total, bool enabled, std::string label)
    : total_(total), enabled_(enabled && total > 0.0), label_(std::move(label)),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void Progress::update(double done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const double f = done / total_ < 0 ? 0 : (done / total_ > 1 ? 1 : done / total_);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = f > 0 ? elapsed * (1.0 - f) / f : 0.0;
  constexpr int width = 30;
  const int filled = static_cast<int>(f * width);
  std::fprintf(stderr, "\r%s[", label_.c_str());
  for (int i = 0; i < width; ++i) std::fputc(i < filled ? '#' : ' ', stderr);
  std::fprintf(stderr, "] %5.1f%%  elapsed %.1fs  ETA %.1fs ", 100.0 * f, elapsed, eta);
  std::fflush(stderr);
}

void Progress::finish() {
  if (!enabled_) return;
  std::fprintf(stderr, "\r%80s\r", "");
  std::fflush(stderr);
}

}  // namespace kolsky
