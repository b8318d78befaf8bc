// DemSystem::for_each_touching_contact: the contacts of the last force evaluation, for models
// that act between steps (the breakage criterion of Sec. 5.2.3 reads each grain's contacts).
// It reads the touching flags the force sweep wrote and recomputes only the geometry of those
// contacts, with the sweep's own formulas (dem_forces.cpp; wall.hpp for the walls), so a
// contact is visited exactly when it produced a force. Serial and in a fixed order (pairs in
// pair order, then wall contacts by slot and particle): its users decide things (which grains
// break) that must not depend on the thread count. A template, so that the caller's
// per-contact work is inlined into the loop.
#pragma once
#include <cmath>
#include <variant>

#include "dem/dem_system.hpp"

namespace kolsky::dem {

template <class Pair, class OnWall>
void DemSystem::for_each_touching_contact(Pair&& pair, OnWall&& wall) const {
  if (!forces_valid_) return;
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    if (!pair_out_.active[k]) continue;
    const int i = pairs_.i[k], j = pairs_.j[k];
    const Vec3 d = p_.x[j] - p_.x[i];
    pair(i, j, d, std::sqrt(dot(d, d)));
  }
  // Wall contacts by slot, each wall's shape resolved once: the kernel's gap and normal
  // (wall.hpp), so the overlap is the one that produced the force.
  for (int s = 0; s < static_cast<int>(walls_.size()); ++s) {
    std::visit(
        [&](const auto& shape) {
          for (int c = wall_first_[s]; c < wall_first_[s + 1]; ++c) {
            if (!wall_out_.active[c]) continue;
            const int i = wall_particle_[c];
            const Vec3& x = p_.x[i];
            wall(i, s, normal_at(shape, x), -gap_at(shape, x, p_.radius[i]), wall_elastic_normal_[c]);
          }
        },
        walls_[s].shape);
  }
}

}  // namespace kolsky::dem
