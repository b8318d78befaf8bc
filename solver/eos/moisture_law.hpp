// K_p(w) and E_o(w) of the three-phase model (Sec. 2.3.6; Fig. 2.9 itself is not in the text).
// The text's rules contradict its printed points (docs/eos.md, "K_p and E_o"); this file holds
// the one reconstruction used everywhere, as piecewise-linear tables in the gravimetric water
// content w (fraction), ends held:
//   E_o: 5 MPa for w <= 7 %, linear to 8 MPa at 11 % and to 20 MPa at 20 %, 20 MPa above.
//   K_p: K_p(0) from the dry initial bulk modulus 145 MPa (Sec. 2.3.4), linear to 155 MPa at
//        3 % and to 120 MPa at 7 %, 120 MPa above 7 %.
#pragma once
#include "core/table.hpp"
#include "eos/three_phase_params.hpp"

namespace kolsky::eos {

struct MoistureLaw {
  Table1D k_p;  ///< K_p (Pa) vs w (fraction)
  Table1D e_o;  ///< E_o (Pa) vs w (fraction)
};

/// K_p that makes the initial tangent dP/deps_v at eps_v = 0 of `params` (its k_p ignored) equal
/// `bulk_modulus` (Pa): Eq. 2.9 at the initial state solved for K_p. Throws
/// std::invalid_argument if friction is 0 or the other branches alone are already stiffer.
double k_p_for_initial_modulus(const ThreePhaseParams& params, double bulk_modulus);

/// The reconstruction above. K_p(0) is computed for `reference` at w = 0 with E_o = 5 MPa (its
/// phase constants, f, B and porosity are used; 238.9 MPa for the defaults).
MoistureLaw dissertation_moisture_law(const ThreePhaseParams& reference = ThreePhaseParams{},
                                      double dry_bulk_modulus = 145e6);

/// `base` with water_content = w (fraction) and K_p(w), E_o(w) from the law.
ThreePhaseParams params_at_water_content(const MoistureLaw& law, ThreePhaseParams base, double w);

}  // namespace kolsky::eos
