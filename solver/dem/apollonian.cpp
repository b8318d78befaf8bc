// Table 5.3 daughters placed in the force frame (see apollonian.hpp).
#include "dem/apollonian.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kolsky::dem {

double retained_volume_fraction() {
  double s = 0;
  for (const auto& d : kApollonianTable) s += d.radius * d.radius * d.radius;
  return s;
}

double lost_volume_fraction() { return 1.0 - retained_volume_fraction(); }

double smallest_daughter_ratio() {
  double r = kApollonianTable[0].radius;
  for (const auto& d : kApollonianTable) r = std::min(r, d.radius);
  return r;
}

Vec3 retained_centroid() {
  Vec3 m{};
  for (const auto& d : kApollonianTable) m += (d.radius * d.radius * d.radius) * d.centre;
  return (1.0 / retained_volume_fraction()) * m;
}

std::array<Vec3, 3> force_frame(Vec3 force_axis, double spin_angle) {
  if (!is_finite(force_axis) || !std::isfinite(spin_angle))
    throw std::invalid_argument("force_frame: force axis and spin angle must be finite");
  const double big =
      std::max({std::abs(force_axis.x), std::abs(force_axis.y), std::abs(force_axis.z)});
  if (!(big > 0)) throw std::invalid_argument("force_frame: the force axis is the zero vector");
  // Scaling by the largest component first keeps norm2 away from underflow (an axis of
  // 1e-200 N is still a direction) and from overflow.
  Vec3 e3 = (1.0 / big) * force_axis;
  e3 = (1.0 / norm(e3)) * e3;
  // The coordinate axis least aligned with e3 makes |e3 x c| >= sqrt(2/3): no cancellation,
  // whatever the axis (also exactly along x, y or z).
  const double ax = std::abs(e3.x), ay = std::abs(e3.y), az = std::abs(e3.z);
  const Vec3 c = (ax <= ay && ax <= az) ? Vec3{1, 0, 0}
                 : (ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  Vec3 e1 = cross(c, e3);
  e1 = (1.0 / norm(e1)) * e1;
  const Vec3 e2 = cross(e3, e1);  // e1 x e2 = e3: right-handed, so no mirror image of the set
  const double cs = std::cos(spin_angle), sn = std::sin(spin_angle);
  return {cs * e1 + sn * e2, cs * e2 - sn * e1, e3};
}

std::array<Daughter, kApollonianCount> place_daughters(Vec3 parent_centre, double parent_radius,
                                                       Vec3 force_axis, double spin_angle) {
  if (!(std::isfinite(parent_radius) && parent_radius > 0))
    throw std::invalid_argument("place_daughters: parent radius must be finite and > 0 m");
  const auto e = force_frame(force_axis, spin_angle);
  std::array<Daughter, kApollonianCount> out;
  for (std::size_t k = 0; k < kApollonianCount; ++k) {
    const Daughter& t = kApollonianTable[k];
    const Vec3 local = t.centre.x * e[0] + t.centre.y * e[1] + t.centre.z * e[2];
    out[k] = {parent_centre + parent_radius * local, parent_radius * t.radius};
  }
  return out;
}

}  // namespace kolsky::dem
