// Continuum materials of the axisymmetric FE model, as small value types:
//   LinearElastic       bars and confining tubes (Sec. 2.3.1: steel E 200 GPa, nu 0.33,
//                       rho 8100; polycarbonate E 1.4 GPa, nu 0.3, rho 1500).
//   PseudoTensorModeI   the specimen (Sec. 2.3.2, LS-DYNA MAT_016 Mode I): pressure from a
//                       tabulated compaction EOS (loading P(eps_v), unloading/reloading along a
//                       bulk modulus from the largest strain reached, no tension), deviatoric
//                       stress elastic with G and capped by a pressure-dependent yield stress
//                       sigma_y(p) = a0 + a1 p, the Mohr-Coulomb compression meridian:
//                       a1 = 6 sin(phi)/(3 - sin(phi)), a0 = 6 c cos(phi)/(3 - sin(phi)).
// Volumetric strain eps_v = 1 - V/V0 (compression +), the Delta V/V0 of Fig. 2.3. Stresses
// inside the FE code are tension positive; the pressure p = -tr(sigma)/3 is compression positive.
#pragma once
#include <algorithm>
#include <array>
#include <limits>
#include <variant>

#include "core/table.hpp"

namespace kolsky::fe {

/// Deviatoric stress at a Gauss point {s_rr, s_zz, s_tt, s_rz} (Pa); s_rr + s_zz + s_tt = 0.
using Deviator = std::array<double, 4>;

struct LinearElastic {
  double youngs_modulus = 200e9;  ///< E, Pa
  double poisson_ratio = 0.33;    ///< nu
  double density = 8100.0;        ///< rho, kg/m^3

  double bulk_modulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
  /// Constrained (P-wave) modulus K + 4G/3, Pa.
  double constrained_modulus() const { return bulk_modulus() + 4.0 / 3.0 * shear_modulus(); }
  /// Throws InputError naming `path` for E <= 0, rho <= 0 or nu outside (-1, 0.5).
  void validate(const char* path) const;
};

/// Radial stiffness per unit inner-wall area p/u(a) of a free-ended (sigma_zz = 0) thick elastic
/// tube, a = inner radius, b = a + thickness: E (b^2 - a^2) / (a [(1 - nu) a^2 + (1 + nu) b^2])
/// (Pa/m; Timoshenko & Goodier 1970, Sec. 28). Thin-wall limit E t / a^2. Here, beside the
/// material, so that the scene layer can use it without the FE body (fuzz/CMakeLists.txt).
double lame_wall_stiffness(const LinearElastic& m, double inner_radius, double thickness);

/// Tabulated compaction EOS (LS-DYNA *EOS_TABULATED_COMPACTION semantics, references.md Sec. 5):
/// P = max(0, P_load(eps_max) - K_u (eps_max - eps_v)), eps_max the largest eps_v reached.
struct CompactionEos {
  Table1D loading;                      ///< x: eps_v (compression +), y: P (Pa); starts at (0, 0)
  double unloading_bulk_modulus = 1e9;  ///< K_u, Pa

  /// Throws InputError naming `path` unless the table starts at (0, 0), rises, and
  /// K_u >= the steepest loading slope (a softer unloading line would return more energy than
  /// the loading absorbed).
  void validate(const char* path) const;
  /// Pressure on the virgin loading curve; the last segment is extended linearly beyond the
  /// table (a held end value would leave the material with no bulk stiffness).
  double loading_pressure(double eps_v) const;
  /// Pressure at eps_v given the history eps_max (>= 0).
  double pressure(double eps_v, double eps_max) const;
  /// Steepest bulk tangent the law can take (sets the wave speed and the time step), Pa.
  double max_tangent() const;
};

struct PseudoTensorModeI {
  double density = 1457.5;          ///< kg/m^3: rho_s (1 - n) with G_s 2.65, n 0.45 (targets 2d)
  double shear_modulus = 50e6;      ///< G, Pa (Sec. 2.3.2)
  double friction_angle_deg = 33.0; ///< phi (Sec. 2.3.2)
  double cohesion = 0.0;            ///< c, Pa (Sec. 2.3.2)
  CompactionEos eos;

  double yield_slope() const;      ///< a1 (-)
  double yield_intercept() const;  ///< a0 (Pa)
  /// sigma_y(p) = max(0, a0 + a1 p) (Pa); von Mises measure sqrt(3/2 s:s).
  double yield_stress(double pressure) const;
  void validate(const char* path) const;
};

using Material = std::variant<LinearElastic, PseudoTensorModeI>;

// Per-material pieces the element kernel calls (overloads, chosen once per part by std::visit).
inline double density(const LinearElastic& m) { return m.density; }
inline double density(const PseudoTensorModeI& m) { return m.density; }
inline double shear_modulus(const LinearElastic& m) { return m.shear_modulus(); }
inline double shear_modulus(const PseudoTensorModeI& m) { return m.shear_modulus; }
/// Steepest bulk tangent (Pa).
inline double max_bulk_tangent(const LinearElastic& m) { return m.bulk_modulus(); }
inline double max_bulk_tangent(const PseudoTensorModeI& m) { return m.eos.max_tangent(); }

/// Pressure (compression +) at eps_v; updates the history eps_max where the law has one.
double update_pressure(const LinearElastic& m, double eps_v, double& eps_max);
double update_pressure(const PseudoTensorModeI& m, double eps_v, double& eps_max);
/// Pressure-dependent cap on the von Mises stress, sigma_y = max(0, a0 + a1 p); prepared once
/// per sweep (LinearElastic: no cap).
struct YieldLine {
  double a0 = std::numeric_limits<double>::infinity(), a1 = 0.0;
  double at(double pressure) const { return std::max(0.0, a0 + a1 * pressure); }
};
inline YieldLine yield_line(const LinearElastic&) { return {}; }
inline YieldLine yield_line(const PseudoTensorModeI& m) { return {m.yield_intercept(), m.yield_slope()}; }
/// Radial return: scales a trial deviator onto sigma_y when its von Mises stress exceeds it;
/// no plastic volume change (the EOS alone governs the volume, MAT_016 Mode I).
void limit_deviator(Deviator& s, double yield_stress);

/// von Mises equivalent stress sqrt(3/2 s:s) of a deviator (Pa).
double mises(const Deviator& s);
/// Fastest dilatational wave speed sqrt((K_max + 4G/3)/rho) of a material (m/s).
double max_wave_speed(const Material& m);
/// Steepest constrained modulus K_max + 4G/3 (Pa).
double max_constrained_modulus(const Material& m);

}  // namespace kolsky::fe
