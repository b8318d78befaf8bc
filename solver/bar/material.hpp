// Elastic bar material and cross-section, with the closed forms every bar model relies on:
// bar wave speed c = sqrt(E/rho) (Sec. 2.3.1), impedance Z = rho c A, and the sphere-chain
// equivalents of Sec. 4.3 (Eqs. 4.3-4.9). SI units throughout.
#pragma once
#include <cmath>
#include <numbers>

#include "core/specimen_geometry.hpp"

namespace kolsky::bar {

struct BarMaterial {
  double youngs_modulus = 200e9;  ///< E, Pa
  double density = 8100.0;        ///< rho, kg/m^3
  double poisson_ratio = 0.33;    ///< nu (dispersion correction only)

  double wave_speed() const { return std::sqrt(youngs_modulus / density); }
  /// Specific impedance rho*c, Pa per (m/s).
  double specific_impedance() const { return density * wave_speed(); }
};

/// A straight cylindrical bar.
struct BarGeometry {
  double length = 1.0;     ///< m
  double diameter = kBarDiameter;  ///< m
  double area() const { return std::numbers::pi * diameter * diameter / 4.0; }
};

/// Sphere-chain equivalents (Sec. 4.3). Each ball of radius R stands for a cylinder of radius R
/// and height 2R.
struct SphereChainProperties {
  double radius;           ///< R = d/2, m
  double ball_density;     ///< Eq. 4.8: rho_ball = 1.5 rho_bar
  double ball_mass;        ///< (4/3) pi R^3 rho_ball
  double ball_stiffness;   ///< Eq. 4.9: k_n^ball = pi R rho c^2 (= E pi R, Eq. 4.7)
  double contact_stiffness;///< Eq. 4.6: F/u = k_n^ball / 2 (two ball stiffnesses in series)
  /// Long-wave speed of the chain, a*sqrt(K/m) with a = 2R; equals c_bar by construction.
  double long_wave_speed() const { return 2.0 * radius * std::sqrt(contact_stiffness / ball_mass); }
  /// Cut-off angular frequency of the chain, 2 sqrt(K/m).
  double cutoff_angular_frequency() const { return 2.0 * std::sqrt(contact_stiffness / ball_mass); }
};

inline SphereChainProperties sphere_chain_properties(const BarMaterial& m, double diameter) {
  SphereChainProperties p{};
  p.radius = diameter / 2.0;
  p.ball_density = 1.5 * m.density;
  p.ball_mass = 4.0 / 3.0 * std::numbers::pi * std::pow(p.radius, 3) * p.ball_density;
  p.ball_stiffness = std::numbers::pi * p.radius * m.density * m.wave_speed() * m.wave_speed();
  p.contact_stiffness = 0.5 * p.ball_stiffness;
  return p;
}

/// Eqs. 4.3/4.4: number of balls N = L / (2R), rounded to the nearest integer.
inline int sphere_count(double length, double diameter) {
  return static_cast<int>(std::lround(length / diameter));
}

}  // namespace kolsky::bar
