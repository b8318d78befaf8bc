// DemSystem::touching_contacts, the listing form of for_each_touching_contact (dem_contacts.hpp).
#include "dem/dem_contacts.hpp"

namespace kolsky::dem {

std::vector<TouchingContact> DemSystem::touching_contacts() const {
  std::vector<TouchingContact> out;
  for_each_touching_contact(
      [&](int i, int j, const Vec3& d, double dist) {
        TouchingContact c;
        c.i = i;
        c.j = j;
        c.normal = dist > 0 ? (1.0 / dist) * d : Vec3{0, 0, 1};
        c.overlap = p_.radius[i] + p_.radius[j] - dist;
        out.push_back(c);
      },
      [&](int i, int slot, const Vec3& normal, double overlap, double force) {
        out.push_back({i, -1, slot, normal, overlap, force});
      });
  return out;
}

}  // namespace kolsky::dem
