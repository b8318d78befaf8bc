// The one Boost.Odeint wrapper of the project: controlled explicit Runge-Kutta steppers, always
// with the tolerances of OdeSettings passed explicitly (odeint's convenience integrate() would
// silently use 1e-6), outputs at given times, step and right-hand-side counts returned so the
// caller can record them. Non-finite states raise kolsky::NumericalError.
// Error control (odeint default_error_checker): |err_i| <= abs_tol + rel_tol (|x_i| + dt |x'_i|).
#pragma once
#include <boost/numeric/odeint/integrate/integrate_times.hpp>
#include <boost/numeric/odeint/integrate/max_step_checker.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_cash_karp54.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace kolsky::eos {

/// Controlled explicit embedded Runge-Kutta pairs (the EOS ODE is not stiff, docs/eos.md).
enum class Stepper { dopri5, cash_karp54, fehlberg78 };

/// "runge_kutta_dopri5", "runge_kutta_cash_karp54", "runge_kutta_fehlberg78" (odeint names).
std::string stepper_name(Stepper s);
/// Accepts the short ("dopri5") or odeint name; throws std::invalid_argument listing the valid
/// names otherwise.
Stepper stepper_from_name(const std::string& name);

struct OdeSettings {
  Stepper stepper = Stepper::dopri5;
  double abs_tol = 1e-10;       ///< absolute tolerance, in the caller's (scaled) state units
  double rel_tol = 1e-10;       ///< relative tolerance
  double first_step = 1e-4;     ///< trial first step in the independent variable; adapted
  int max_steps = 1000000;      ///< steps allowed between two outputs before giving up
};

/// Throws std::invalid_argument naming the first bad field (tolerances > 0, first_step > 0).
void validate(const OdeSettings& s);

struct OdeStats {
  std::size_t n_steps = 0;  ///< accepted steps (as counted by odeint)
  std::size_t n_rhs = 0;    ///< right-hand-side evaluations, rejected trials included
};

/// Integrates dy/dt = system(y, t) from times.front() through every entry of `times` (strictly
/// increasing), calling observer(y, t) at each (the first call sees the initial state). y holds
/// the state at times.back() on return. Prefer std::vector states: odeint copies its steppers,
/// and a std::array state makes GCC warn about their uninitialized scratch arrays.
template <class System, class State, class Observer>
OdeStats integrate_observed(System system, State& y, const std::vector<double>& times,
                            const OdeSettings& s, Observer observer) {
  namespace odeint = boost::numeric::odeint;
  validate(s);
  OdeStats stats;
  auto counted = [&system, &stats](const State& x, State& dxdt, double t) {
    ++stats.n_rhs;
    system(x, dxdt, t);
  };
  auto checked = [&observer](const State& x, double t) {
    for (double v : x)
      if (!std::isfinite(v)) throw NumericalError("ODE state became non-finite", t);
    observer(x, t);
  };
  auto run = [&](auto stepper) {
    return odeint::integrate_times(odeint::make_controlled(s.abs_tol, s.rel_tol, stepper),
                                   counted, y, times.begin(), times.end(), s.first_step, checked,
                                   odeint::max_step_checker(s.max_steps));
  };
  switch (s.stepper) {
    case Stepper::dopri5: stats.n_steps = run(odeint::runge_kutta_dopri5<State>()); break;
    case Stepper::cash_karp54: stats.n_steps = run(odeint::runge_kutta_cash_karp54<State>()); break;
    case Stepper::fehlberg78: stats.n_steps = run(odeint::runge_kutta_fehlberg78<State>()); break;
  }
  return stats;
}

}  // namespace kolsky::eos
