// Parameters of the three-phase (Kandaurs) soil model of Henrych (1979) as modified by Wang et
// al. (2004), Sec. 2.3.6, Eqs. 2.1-2.9, with the printed constants as defaults, and the initial
// phase volumes from porosity and gravimetric water content (Eq. 2.2).
// Units: SI. Volumes are per unit initial total volume (V0 = 1), so K_p and E_o are pressures
// (Pa per unit volume fraction; the text's K_p = 155, E_o = 5 are read as MPa, docs/eos.md).
#pragma once
#include "eos/phase_eos.hpp"

namespace kolsky::eos {

struct ThreePhaseParams {
  TaitEos water = kWaterEos;    ///< Eq. 2.3
  TaitEos solid = kQuartzEos;   ///< Eq. 2.4
  AdiabaticGas air = kAirEos;   ///< Eq. 2.5
  double friction = 0.56;       ///< f of Eq. 2.6, inter-particle friction coefficient
  double k_p = 155e6;           ///< K_p of Eq. 2.6, Pa (printed value at w = 3 %)
  double e_o = 5e6;             ///< E_o of Eq. 2.8, Pa (printed value at w = 3 %)
  double b = -5.0;              ///< B of Eq. 2.8, per unit volume fraction; all water contents
  double porosity = 0.45;       ///< n = V_p0 / V0 (Sec. 2.2)
  double water_content = 0.03;  ///< w = mass of water / mass of solid (fraction, not percent)
};

/// Volumes of the three phases per unit initial total volume.
struct PhaseVolumes {
  double solid = 0.0;
  double water = 0.0;
  double air = 0.0;
  double voids() const { return water + air; }  ///< V_p = V_a + V_w (Eq. 2.2)
  double total() const { return solid + water + air; }
};

/// Eq. 2.2 at the initial state: V_s = 1 - n, V_w = w (rho_s/rho_w) V_s, V_a = n - V_w.
/// Throws std::invalid_argument if n is outside (0, 1), w < 0, or the water overfills the voids.
PhaseVolumes initial_volumes(double porosity, double water_content, double rho_solid,
                             double rho_water);

/// Water content (fraction) that fills the voids, S_r = 1: n rho_w / ((1 - n) rho_s).
/// 0.3087 for n = 0.45 and the printed densities.
double saturation_water_content(double porosity, double rho_solid, double rho_water);

/// Throws std::invalid_argument("<field>: <rule>") for the first violated rule: phase constants
/// positive, f, K_p, E_o >= 0, B finite, n in (0, 1), 0 <= w <= saturation.
void validate(const ThreePhaseParams& p);

}  // namespace kolsky::eos
