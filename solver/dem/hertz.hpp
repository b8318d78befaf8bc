// Hertz's elastic normal contact between two spheres or a sphere and a plane (Johnson 1985,
// Sec. 4.2; dissertation Eqs. 4.10 and 5.13): the force of an overlap and the effective
// modulus, written once for the laws' closed forms, the packing census and the breakage
// criteria. The law's per-contact kernel (contact_pieces.hpp, HertzNormal) evaluates the same
// force with sqrt(r') sqrt(delta) fused into one root, the form it needs for its stiffness.
// SI units: Pa, m, N.
#pragma once
#include <cmath>

namespace kolsky::dem {

/// F = (4/3) E' sqrt(r') delta^(3/2) (N) for overlap delta >= 0 (m), effective radius r' (m)
/// and effective modulus E' (Pa).
inline double hertz_normal_force(double e_eff, double r_eff, double overlap) {
  return 4.0 / 3.0 * e_eff * std::sqrt(r_eff) * overlap * std::sqrt(overlap);
}

/// E' = ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)^-1 (Pa); a body with E = +inf (a rigid wall) drops
/// its term.
inline double effective_modulus(double e1, double nu1, double e2, double nu2) {
  const double c1 = std::isinf(e1) ? 0.0 : (1 - nu1 * nu1) / e1;
  const double c2 = std::isinf(e2) ? 0.0 : (1 - nu2 * nu2) / e2;
  return 1.0 / (c1 + c2);
}

/// r' = (1/r1 + 1/r2)^-1 (m); r2 = +inf (a plane wall) gives r1 exactly.
inline double effective_radius(double r1, double r2) {
  if (std::isinf(r2)) return r1;
  return r1 * r2 / (r1 + r2);
}

}  // namespace kolsky::dem
