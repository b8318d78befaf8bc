#include "bar/pulse.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kolsky::bar {

double TrapezoidPulse::operator()(double t) const {
  const double s = t - delay;
  if (s <= 0.0 || s >= duration) return 0.0;
  if (s < rise_time) return amplitude * s / rise_time;
  if (s > duration - fall_time) return amplitude * (duration - s) / fall_time;
  return amplitude;
}

double HalfSinePulse::operator()(double t) const {
  const double s = t - delay;
  if (s <= 0.0 || s >= duration) return 0.0;
  return amplitude * std::sin(std::numbers::pi * s / duration);
}

double TabulatedPulse::operator()(double t) const {
  const double s = t - delay;
  if (table.empty() || s < table.x.front() || s > table.x.back()) return 0.0;
  return scale * table(s);
}

double evaluate(const Pulse& p, double t) {
  return std::visit([t](const auto& pulse) { return pulse(t); }, p);
}

double end_time(const Pulse& p) {
  struct {
    double operator()(const TrapezoidPulse& q) const { return q.delay + q.duration; }
    double operator()(const HalfSinePulse& q) const { return q.delay + q.duration; }
    double operator()(const TabulatedPulse& q) const {
      return q.delay + (q.table.empty() ? 0.0 : q.table.x.back());
    }
  } visitor;
  return std::visit(visitor, p);
}

double peak_stress(const Pulse& p) {
  struct {
    double operator()(const TrapezoidPulse& q) const { return std::fabs(q.amplitude); }
    double operator()(const HalfSinePulse& q) const { return std::fabs(q.amplitude); }
    double operator()(const TabulatedPulse& q) const {
      double m = 0.0;
      for (double y : q.table.y) m = std::max(m, std::fabs(y));
      return m * std::fabs(q.scale);
    }
  } visitor;
  return std::visit(visitor, p);
}

}  // namespace kolsky::bar
