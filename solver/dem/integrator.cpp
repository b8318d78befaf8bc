// The grains' kick-drift-kick integrator (integrator.hpp).
#include "dem/integrator.hpp"

#include <algorithm>
#include <cmath>

namespace kolsky::dem {

double RollingRetardation::factor(double dt) const {
  if (factor_per_reference_step == 1.0 || factor_per_reference_step == 0.0)
    return factor_per_reference_step;
  return std::pow(factor_per_reference_step, dt / reference_dt);
}

namespace {
// The half kick of grain i, v += (h/m) f and omega += (h/I) T, over raw pointers so that the
// parallel loops below stay plain arrays.
struct HalfKick {
  Vec3* v;
  Vec3* w;
  const Vec3* f;
  const Vec3* t;
  const double* m;
  const double* in;
  explicit HalfKick(Particles& p)
      : v(p.v.data()), w(p.omega.data()), f(p.f.data()), t(p.torque.data()), m(p.mass.data()), in(p.inertia.data()) {}
  void operator()(std::ptrdiff_t i, double h) const {
    v[i] += (h / m[i]) * f[i];
    w[i] += (h / in[i]) * t[i];
  }
};
}  // namespace

double kick_drift(Particles& p, double h, double dt, const Vec3* x_at_build, double max_disp2) {
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  const HalfKick kick(p);
  Vec3* x = p.x.data();
  const Vec3* v = p.v.data();
  const bool track = x_at_build != nullptr;
  double md = max_disp2;
#pragma omp parallel for schedule(static) reduction(max : md) if (n >= kIntegratorParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    kick(i, h);
    x[i] += dt * v[i];
    if (track) md = std::max(md, norm2(x[i] - x_at_build[i]));
  }
  return md;
}

void kick_retard(Particles& p, double h, double k, std::vector<double>& dissipated) {
  const bool retarding = k != 1.0;
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  const HalfKick kick(p);
  Vec3* w = p.omega.data();
  const double* in = p.inertia.data();
  double* d = dissipated.data();
#pragma omp parallel for schedule(static) if (n >= kIntegratorParallelMin)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    kick(i, h);
    if (retarding) {
      d[i] += 0.5 * in[i] * norm2(w[i]) * (1 - k * k);
      w[i] *= k;
    }
  }
}

}  // namespace kolsky::dem
