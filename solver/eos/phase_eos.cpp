// Phase EOSs, Eqs. 2.3-2.5 (see phase_eos.hpp).
#include "eos/phase_eos.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace kolsky::eos {

double pressure(const TaitEos& e, double rho) {
  return e.p0 + e.rho0 * e.c0 * e.c0 / e.k * (std::pow(rho / e.rho0, e.k) - 1.0);
}

double density(const TaitEos& e, double p) {
  // (rho/rho0)^k = 1 + k (p - p0) / (rho0 c0^2); the bracket must stay positive.
  const double base = 1.0 + e.k * (p - e.p0) / (e.rho0 * e.c0 * e.c0);
  if (!(base > 0.0))
    throw std::domain_error("Tait EOS: no density at p = " + std::to_string(p) +
                            " Pa (below the tension cut-off)");
  return e.rho0 * std::pow(base, 1.0 / e.k);
}

double volume_ratio(const TaitEos& e, double p) { return e.rho0 / density(e, p); }

double bulk_modulus(const TaitEos& e, double p) {
  // rho dp/drho = rho0 c0^2 (rho/rho0)^k, and (rho/rho0)^k is linear in p by Eq. 2.3.
  return e.rho0 * e.c0 * e.c0 + e.k * (p - e.p0);
}

double sound_speed(const TaitEos& e, double p) { return std::sqrt(bulk_modulus(e, p) / density(e, p)); }

double pressure(const AdiabaticGas& e, double rho) { return e.p0 * std::pow(rho / e.rho0, e.k); }

double density(const AdiabaticGas& e, double p) {
  if (!(p > 0.0))
    throw std::domain_error("adiabatic gas: no density at p = " + std::to_string(p) + " Pa");
  return e.rho0 * std::pow(p / e.p0, 1.0 / e.k);
}

double volume_ratio(const AdiabaticGas& e, double p) { return e.rho0 / density(e, p); }

double bulk_modulus(const AdiabaticGas& e, double p) { return e.k * p; }

double sound_speed(const AdiabaticGas& e, double p) { return std::sqrt(e.k * p / density(e, p)); }

}  // namespace kolsky::eos
