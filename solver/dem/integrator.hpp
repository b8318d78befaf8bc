// The grains' time integrator, a component over the particle arrays (no walls, no contacts):
// velocity Verlet as kick-drift-kick, translational and rotational, with the rotational
// retardation of Eqs. 4.12-4.14 after the second half kick. DemSystem::begin_step and
// finish_step call it and then move the walls. Each function is one pass over the grains (one
// parallel region), doing per grain the same operations in the same order as separate kick,
// drift and retardation loops would, so its results are bitwise theirs whatever the threads.
#pragma once
#include <cstddef>
#include <vector>

#include "dem/particles.hpp"

namespace kolsky::dem {

/// Grains at or above this count are integrated in parallel (OpenMP); fewer: one thread, since
/// a parallel region costs microseconds, which would dominate the one- and two-grain checks.
inline constexpr std::ptrdiff_t kIntegratorParallelMin = 2048;

/// Rotational resistance by angular-velocity retardation, Eqs. 4.12-4.14.
struct RollingRetardation {
  double factor_per_reference_step = 1.0;  ///< k_lambda^zeta per reference step (1: none), -
  double reference_dt = 1e-9;              ///< step the factor was given for, s

  /// k_run = k_ref^(dt / dt_ref); 0 stays 0 (full restraint), 1 stays 1 (0.99999975 per 1 ns,
  /// Sec. 4.3, gives k_run = 0.99999975^(dt / 1 ns)).
  double factor(double dt) const;
};

/// Half kick v += (h/m) f, omega += (h/I) T, then drift x += dt v. With x_at_build non-null,
/// returns the larger of max_disp2 and the largest |x - x_at_build|^2 after the drift (the
/// neighbour list's displacement test); else returns max_disp2 unchanged.
double kick_drift(Particles& p, double h, double dt, const Vec3* x_at_build, double max_disp2);

/// Second half kick, then omega *= k (rolling retardation factor for this dt; 1: none), the
/// rotational energy removed, 0.5 I |omega|^2 (1 - k^2), added to dissipated[i] (J).
void kick_retard(Particles& p, double h, double k, std::vector<double>& dissipated);

}  // namespace kolsky::dem
