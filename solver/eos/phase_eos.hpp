// Phase equations of state of the three-phase soil model (Sec. 2.3.6; Lyakhov et al. 1972).
//   Eq. 2.3 (water) and Eq. 2.4 (solid grains), Tait/Murnaghan form:
//     p = p0 + (rho0 c0^2 / k) [(rho/rho0)^k - 1]
//   Eq. 2.5 (air), isentrope: p = p0 (rho/rho0)^k
// Each law comes with its inverse (density, volume ratio at a pressure) and its tangent bulk
// modulus K = rho dp/drho, which is what the mixture ODE (Eq. 2.9) needs. SI: Pa, kg/m^3, m/s.
#pragma once

namespace kolsky::eos {

/// Eq. 2.3/2.4: a liquid or solid phase. Its bulk modulus at rho0 is rho0 c0^2.
struct TaitEos {
  double rho0;  ///< reference density, kg/m^3
  double c0;    ///< sound speed at rho0, m/s
  double k;     ///< exponent (7 water, 3 solid grains)
  double p0;    ///< pressure at rho0, Pa (p_wo, p_so: not printed; taken = P_ao)
};

/// Eq. 2.5: air compressed isentropically.
struct AdiabaticGas {
  double p0;    ///< initial pressure P_ao, Pa
  double rho0;  ///< initial density rho_ao, kg/m^3
  double k;     ///< isentropic exponent k_a
};

/// The printed constants of Sec. 2.3.6. p_wo = p_so are not printed; they equal P_ao so that
/// every phase starts at its reference density under the same ambient pressure.
inline constexpr TaitEos kWaterEos{1000.0, 1500.0, 7.0, 100e3};
inline constexpr TaitEos kQuartzEos{2650.0, 4500.0, 3.0, 100e3};
inline constexpr AdiabaticGas kAirEos{100e3, 1.225, 1.4};

/// Eq. 2.3/2.4: pressure (Pa) at density rho (kg/m^3, > 0).
double pressure(const TaitEos& e, double rho);
/// Inverse of Eq. 2.3/2.4. Throws std::domain_error where no density exists
/// (p <= p0 - rho0 c0^2 / k, the tension cut-off of the Tait form).
double density(const TaitEos& e, double p);
/// V/V0 = rho0/rho(p) for a fixed mass.
double volume_ratio(const TaitEos& e, double p);
/// Tangent bulk modulus K = rho dp/drho = rho0 c0^2 + k (p - p0), Pa (linear in p).
double bulk_modulus(const TaitEos& e, double p);
/// Sound speed sqrt(K/rho), m/s; equals c0 at p0.
double sound_speed(const TaitEos& e, double p);

/// Eq. 2.5: pressure (Pa) at density rho.
double pressure(const AdiabaticGas& e, double rho);
/// Inverse of Eq. 2.5; throws std::domain_error for p <= 0.
double density(const AdiabaticGas& e, double p);
/// V/V0 = (p0/p)^(1/k).
double volume_ratio(const AdiabaticGas& e, double p);
/// Isentropic bulk modulus K = k p, Pa.
double bulk_modulus(const AdiabaticGas& e, double p);
/// Sound speed sqrt(k p / rho), m/s.
double sound_speed(const AdiabaticGas& e, double p);

}  // namespace kolsky::eos
