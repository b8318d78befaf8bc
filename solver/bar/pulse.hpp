// Incident stress histories applied at the free end of the incident bar (compression positive,
// Pa, time from the start of loading at the free end). A pulse family is a std::variant; the
// scene picks one by name ("trapezoid", "half_sine", "tabulated").
#pragma once
#include <variant>

#include "core/table.hpp"

namespace kolsky::bar {

/// Linear rise over rise_time, flat top, linear fall over fall_time; total length `duration`
/// (rise + flat + fall), starting at `delay`.
struct TrapezoidPulse {
  double amplitude = 100e6;
  double rise_time = 50e-6;
  double duration = 300e-6;
  double fall_time = 50e-6;
  double delay = 0.0;
  double operator()(double t) const;
};

/// amplitude * sin(pi (t - delay) / duration) on [delay, delay + duration].
struct HalfSinePulse {
  double amplitude = 100e6;
  double duration = 300e-6;
  double delay = 0.0;
  double operator()(double t) const;
};

/// Tabulated stress history (e.g. a reconstructed experimental pulse), times `scale`, zero
/// outside the table's time range.
struct TabulatedPulse {
  Table1D table;  ///< x: time (s), y: stress (Pa)
  double scale = 1.0;
  double delay = 0.0;
  double operator()(double t) const;
};

using Pulse = std::variant<TrapezoidPulse, HalfSinePulse, TabulatedPulse>;

/// Stress of the pulse at time t (Pa).
double evaluate(const Pulse& p, double t);
/// Time after which the pulse is identically zero (s).
double end_time(const Pulse& p);
/// Largest |stress| of the pulse (Pa): the amplitude, or the table's largest |stress| x scale.
double peak_stress(const Pulse& p);

}  // namespace kolsky::bar
