// Damping coefficients from a coefficient of restitution e.
//   Linear spring-dashpot: zeta = -ln e / sqrt(pi^2 + ln^2 e), exact inverse of
//     e = exp(-zeta pi / sqrt(1 - zeta^2)) (damped oscillator, no clamp on the dashpot force).
//   Hertz with Tsuji damping c = 2 sqrt(5/6) beta sqrt(S_n m*), S_n = 2 E* sqrt(R* delta)
//     (LIGGGHTS hertz model) with the same beta(e): the restitution of this model does not
//     depend on the impact velocity, and with the sqrt(5/6) factor it equals the linear
//     formula exactly (Antypov & Elliott 2011, EPL 94:50004). hertz_restitution() checks this by
//     integrating the nondimensional impact x'' = -x^{3/2} - sqrt(5) beta x^{1/4} x',
//     x(0) = 0, x'(0) = 1, e = -x'(end) (RK4).
#pragma once

namespace kolsky::dem {

/// Damping ratio zeta (linear) or Tsuji beta (Hertz) for restitution e in (0, 1].
/// Throws std::invalid_argument outside (0, 1].
double damping_ratio_from_restitution(double e);
/// e = exp(-zeta pi / sqrt(1 - zeta^2)) for zeta in [0, 1); 0 for zeta >= 1 (overdamped).
double linear_restitution(double zeta);
/// Restitution of a Hertz impact with Tsuji damping beta >= 0, by integrating the
/// nondimensional impact with RK4 (relative accuracy about 1e-6).
double hertz_restitution(double beta);

}  // namespace kolsky::dem
