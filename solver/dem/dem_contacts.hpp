// DemSystem::for_each_touching_contact: the contacts of the last force evaluation, for models
// that act between steps (the breakage criterion of Sec. 5.2.3 reads each grain's contacts).
// It reads the touching flags the force sweep wrote and recomputes only the geometry of those
// contacts, with the sweep's own formulas (dem_forces.cpp), so a contact is visited exactly when
// it produced a force. Serial and in a fixed order (pairs in pair order, then wall contacts by
// slot and particle): its users decide things (which grains break) that must not depend on the
// thread count. A template, so that the caller's per-contact work is inlined into the loop.
#pragma once
#include <cmath>

#include "dem/dem_system.hpp"

namespace kolsky::dem {

template <class Pair, class Wall>
void DemSystem::for_each_touching_contact(Pair&& pair, Wall&& wall) const {
  if (!forces_valid_) return;
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    if (!pair_out_.active[k]) continue;
    const int i = pairs_.i[k], j = pairs_.j[k];
    const Vec3 d = p_.x[j] - p_.x[i];
    pair(i, j, d, std::sqrt(dot(d, d)));
  }
  const WallSlots slots{n_planes(), n_cylinders()};
  for (int s = 0; s < slots.count(); ++s) {
    for (int c = wall_first_[s]; c < wall_first_[s + 1]; ++c) {
      if (!wall_out_.active[c]) continue;
      const int i = wall_particle_[c];
      Vec3 normal;
      double overlap = 0.0;
      if (slots.kind(s) == WallKind::plane) {
        const PlaneState& w = planes_[slots.index(s)];
        const Vec3 base = w.wall.point + plane_offset_at(w, p_.x[i]) * w.wall.normal;
        normal = -w.wall.normal;
        overlap = p_.radius[i] - dot(p_.x[i] - base, w.wall.normal);
      } else {
        const TubeState& w = tubes_[slots.index(s)];
        const double dx = p_.x[i].x - w.wall.cx, dy = p_.x[i].y - w.wall.cy;
        const double rho = std::sqrt(dx * dx + dy * dy);
        normal = rho > 0 ? Vec3{dx / rho, dy / rho, 0} : Vec3{1, 0, 0};
        overlap = p_.radius[i] + rho - tube_radius_at(w, p_.x[i]);
      }
      wall(i, s, normal, overlap, wall_elastic_normal_[c]);
    }
  }
}

}  // namespace kolsky::dem
