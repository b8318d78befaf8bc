// Two-body impact runner (see impact.hpp).
#include "dem/impact.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kolsky::dem {

namespace {
// Normal force of the watched contact, repulsive positive.
double watched_force(const DemSystem& sys) {
  const Particles& p = sys.particles();
  if (p.size() >= 2) {
    const Vec3 d = p.x[1] - p.x[0];
    return -dot(p.f[0], (1.0 / norm(d)) * d);
  }
  return sys.plane_force(0);
}
}  // namespace

double watched_overlap(const DemSystem& sys) {
  const Particles& p = sys.particles();
  if (p.size() >= 2) return p.radius[0] + p.radius[1] - norm(p.x[1] - p.x[0]);
  const PlaneWall& w = sys.plane(0);
  return p.radius[0] - dot(p.x[0] - w.point - sys.plane_offset(0) * w.normal, w.normal);
}

namespace {
// Peak of the parabola through three equally spaced samples around a sampled maximum: removes
// the O(dt^2) sampling error of taking the largest sample.
double parabolic_peak(const std::vector<double>& y) {
  const auto k = static_cast<std::size_t>(std::max_element(y.begin(), y.end()) - y.begin());
  if (k == 0 || k + 1 >= y.size()) return y[k];
  const double curvature = y[k - 1] - 2 * y[k] + y[k + 1];
  if (curvature >= 0) return y[k];
  const double slope = y[k + 1] - y[k - 1];
  return y[k] - slope * slope / (8 * curvature);
}
}  // namespace

ImpactRecord run_impact(DemSystem& sys, double dt, int max_steps) {
  ImpactRecord r;
  double before = watched_overlap(sys), t_start = 0;
  bool touching = before > 0;
  std::vector<double> overlap, force;
  for (r.steps = 0; r.steps < max_steps; ++r.steps) {
    const double t0 = sys.time();
    sys.step(dt);
    const double now = watched_overlap(sys);
    if (!touching && now > 0) {
      touching = true;
      t_start = t0 + dt * before / (before - now);
    }
    if (touching) {
      if (now <= 0) {
        r.contact_time = t0 + dt * before / (before - now) - t_start;
        r.separated = true;
        ++r.steps;
        break;
      }
      overlap.push_back(now);
      force.push_back(watched_force(sys));
    }
    before = now;
  }
  if (!overlap.empty()) {
    r.max_overlap = parabolic_peak(overlap);
    r.peak_force = parabolic_peak(force);
  }
  return r;
}

}  // namespace kolsky::dem
