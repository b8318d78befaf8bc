#include "core/stability_check.hpp"

#include <iomanip>
#include <sstream>

#include "core/errors.hpp"

namespace kolsky {

void check_time_step(double dt, double limit, const std::string& who, double t, const std::string& limit_is) {
  if (dt > 0.0 && dt <= limit * (1 + 1e-12)) return;
  std::ostringstream msg;
  msg << std::setprecision(6) << who << ": time step " << dt << " s is above the stable limit " << limit
      << " s at t = " << t << " s (" << limit_is << ")";
  throw NumericalError(msg.str(), t);
}

void check_energy_growth(const EnergyLedger& e, double tolerance, const std::string& who, double t) {
  if (!(e.scale > 0.0) || !(e.excess() > tolerance * e.scale)) return;
  std::ostringstream msg;
  msg << std::setprecision(4) << who << ": energy grows: the model holds " << e.held << " J but only "
      << e.supplied << " J was supplied (t = " << t << " s; bound " << tolerance << " x " << e.scale
      << " J): unstable step?";
  throw NumericalError(msg.str(), t);
}

}  // namespace kolsky
