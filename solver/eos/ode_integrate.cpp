// Stepper names and settings validation for the Odeint wrapper (see ode_integrate.hpp).
#include "eos/ode_integrate.hpp"

#include <stdexcept>

namespace kolsky::eos {

std::string stepper_name(Stepper s) {
  switch (s) {
    case Stepper::dopri5: return "runge_kutta_dopri5";
    case Stepper::cash_karp54: return "runge_kutta_cash_karp54";
    case Stepper::fehlberg78: return "runge_kutta_fehlberg78";
  }
  return "unknown";
}

Stepper stepper_from_name(const std::string& name) {
  for (Stepper s : {Stepper::dopri5, Stepper::cash_karp54, Stepper::fehlberg78}) {
    const std::string full = stepper_name(s);
    if (name == full || name == full.substr(std::string("runge_kutta_").size())) return s;
  }
  throw std::invalid_argument("unknown stepper '" + name +
                              "' (valid: dopri5, cash_karp54, fehlberg78)");
}

void validate(const OdeSettings& s) {
  if (!(s.abs_tol > 0.0) || !std::isfinite(s.abs_tol))
    throw std::invalid_argument("abs_tol: must be finite and > 0");
  if (!(s.rel_tol > 0.0) || !std::isfinite(s.rel_tol))
    throw std::invalid_argument("rel_tol: must be finite and > 0");
  if (!(s.first_step > 0.0) || !std::isfinite(s.first_step))
    throw std::invalid_argument("first_step: must be finite and > 0");
  if (s.max_steps < 1) throw std::invalid_argument("max_steps: must be >= 1");
}

}  // namespace kolsky::eos
