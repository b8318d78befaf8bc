// Wall helpers: velocity histories, tube stiffness and mass, validation (see walls.hpp).
#include "dem/walls.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace kolsky::dem {

double VelocityHistory::at(double t) const {
  if (t <= time.front()) return speed.front();
  if (t >= time.back()) return speed.back();
  const auto it = std::upper_bound(time.begin(), time.end(), t);
  const std::size_t k = static_cast<std::size_t>(it - time.begin());
  const double s = (t - time[k - 1]) / (time[k] - time[k - 1]);
  return speed[k - 1] + s * (speed[k] - speed[k - 1]);
}

double VelocityHistory::displacement(double t0, double t1) const {
  // Trapezoids between t0, every table time inside (t0, t1), and t1: exact for a
  // piecewise-linear speed.
  double sum = 0, ta = t0, va = at(t0);
  for (double tk : time) {
    if (tk <= t0 || tk >= t1) continue;
    const double vk = at(tk);
    sum += 0.5 * (va + vk) * (tk - ta);
    ta = tk;
    va = vk;
  }
  return sum + 0.5 * (va + at(t1)) * (t1 - ta);
}

std::pair<int, double> WallProfile::segment(double s) const {
  const auto n = static_cast<int>(station.size());
  if (s <= station.front()) return {0, 0.0};
  if (s >= station.back()) return {n - 2, 1.0};
  const int k = static_cast<int>(std::upper_bound(station.begin(), station.end(), s) - station.begin()) - 1;
  return {k, (s - station[k]) / (station[k + 1] - station[k])};
}

WallProfile::Sample WallProfile::at(double s) const {
  // Plain copies, not a structured binding: clang 14 (the sanitizer build) cannot capture one.
  const std::pair<int, double> seg = segment(s);
  const int k = seg.first;
  const double w = seg.second;
  auto lerp = [k, w](const std::vector<double>& v) { return (1 - w) * v[k] + w * v[k + 1]; };
  return {lerp(offset), lerp(normal_speed), lerp(tangential_speed)};
}

void validate(const WallProfile& p, const char* path) {
  const std::string at(path);
  const std::size_t n = p.station.size();
  if (n < 2 || p.offset.size() != n || p.normal_speed.size() != n || p.tangential_speed.size() != n)
    throw InputError("", at, "station, offset, normal_speed and tangential_speed need one size >= 2");
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(p.station[k]) || !std::isfinite(p.offset[k]) || !std::isfinite(p.normal_speed[k]) ||
        !std::isfinite(p.tangential_speed[k]))
      throw InputError("", at, "every value must be finite");
    if (k > 0 && !(p.station[k] > p.station[k - 1]))
      throw InputError("", at + ".station", "must be strictly increasing");
  }
}

double TubeCompliance::radial_stiffness(double radius) const {
  if (wall_stiffness > 0) return 2 * std::numbers::pi * radius * height * wall_stiffness;
  return 2 * std::numbers::pi * height * youngs_modulus * thickness / radius;
}

double TubeCompliance::radial_mass(double radius) const {
  return density * 2 * std::numbers::pi * radius * thickness * height;
}

void validate(const PlaneWall& w, const char* path) {
  const std::string at(path);
  if (std::abs(norm(w.normal) - 1) > 1e-12)
    throw InputError("", at + ".normal", "must be a unit vector");
  if (!is_finite(w.point)) throw InputError("", at + ".point", "must be finite");
  std::visit([&](const auto& law) { law.validate(at + ".law"); }, w.law);
  if (const auto* p = std::get_if<PrescribedPlane>(&w.motion)) {
    const auto& h = p->velocity;
    if (h.time.empty() || h.time.size() != h.speed.size())
      throw InputError("", at + ".velocity", "time and speed need the same length >= 1");
    for (std::size_t k = 1; k < h.time.size(); ++k)
      if (!(h.time[k] > h.time[k - 1]))
        throw InputError("", at + ".velocity.time", "must be strictly increasing");
  }
}

void validate(const CylinderWall& w, const char* path) {
  const std::string at(path);
  if (!(w.radius > 0)) throw InputError("", at + ".radius", "must be > 0");
  std::visit([&](const auto& law) { law.validate(at + ".law"); }, w.law);
  if (w.compliance) {
    const auto& c = *w.compliance;
    if (!(c.youngs_modulus > 0) || !(c.thickness > 0) || !(c.density > 0) || !(c.height > 0))
      throw InputError("", at + ".compliance",
                       "youngs_modulus, thickness, density and height must be > 0");
  }
}

}  // namespace kolsky::dem
