// DemSystem::touching_contacts: the contacts of the last force evaluation for models that act
// between steps (the breakage criterion of Sec. 5.2.3 reads each grain's contacts). It reads
// the touching flags the force sweep wrote and recomputes only the geometry (overlap, normal)
// of those contacts, with the sweep's own formulas (dem_forces.cpp), so a contact is listed
// exactly when it produced a force. Serial and in a fixed order: its users decide things
// (which grains break) that must not depend on the thread count.
#include <cmath>

#include "dem/dem_system.hpp"

namespace kolsky::dem {

std::vector<TouchingContact> DemSystem::touching_contacts() const {
  std::vector<TouchingContact> out;
  if (!forces_valid_) return out;
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    if (!pair_out_.active[k]) continue;
    const int i = pairs_.i[k], j = pairs_.j[k];
    const Vec3 d = p_.x[j] - p_.x[i];
    const double dist = norm(d);
    TouchingContact c;
    c.i = i;
    c.j = j;
    c.normal = dist > 0 ? (1.0 / dist) * d : Vec3{0, 0, 1};
    c.overlap = p_.radius[i] + p_.radius[j] - dist;
    out.push_back(c);
  }
  const WallSlots slots{n_planes(), n_cylinders()};
  for (int s = 0; s < slots.count(); ++s) {
    for (int c = wall_first_[s]; c < wall_first_[s + 1]; ++c) {
      if (!wall_out_.active[c]) continue;
      const int i = wall_particle_[c];
      TouchingContact t;
      t.i = i;
      t.wall_slot = s;
      t.wall_force = wall_normal_[c];
      if (slots.kind(s) == WallKind::plane) {
        const PlaneState& w = planes_[slots.index(s)];
        const Vec3 base = w.wall.point + w.offset * w.wall.normal;
        t.normal = -w.wall.normal;
        t.overlap = p_.radius[i] - dot(p_.x[i] - base, w.wall.normal);
      } else {
        const TubeState& w = tubes_[slots.index(s)];
        const double dx = p_.x[i].x - w.wall.cx, dy = p_.x[i].y - w.wall.cy;
        const double rho = std::sqrt(dx * dx + dy * dy);
        t.normal = rho > 0 ? Vec3{dx / rho, dy / rho, 0} : Vec3{1, 0, 0};
        t.overlap = p_.radius[i] + rho - (w.wall.radius + w.u);
      }
      out.push_back(t);
    }
  }
  return out;
}

}  // namespace kolsky::dem
