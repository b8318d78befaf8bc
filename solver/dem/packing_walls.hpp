// The walls of a packing cylinder (r < R around the z axis, 0 < z < L) and their mean stress:
// shared by the packing stages (packing.cpp) and the pre-stress (prestress.cpp). SI units.
#pragma once
#include <numbers>
#include <optional>

#include "dem/dem_system.hpp"

namespace kolsky::dem {

/// Adds the tube (cylinder 0), the bottom plane z = 0 (plane 0) and the top plane z = L
/// (plane 1), all fixed and with one law.
inline void add_packing_walls(DemSystem& sys, double R, double L, const WallLaw& law) {
  sys.add_cylinder(CylinderWall{0, 0, R, std::nullopt, law});
  sys.add_plane(PlaneWall{{0, 0, 0}, {0, 0, 1}, FixedPlane{}, law});
  sys.add_plane(PlaneWall{{0, 0, L}, {0, 0, -1}, FixedPlane{}, law});
}

/// Mean stress (compression +) from the wall forces: (sigma_zz + 2 sigma_rr)/3 with
/// sigma_zz = mean end-plane force / (pi R^2), sigma_rr = tube force / (2 pi R L), Pa.
inline double wall_mean_stress(const DemSystem& sys, double R, double L) {
  constexpr double pi = std::numbers::pi;
  const double szz = 0.5 * (sys.plane_force(0) + sys.plane_force(1)) / (pi * R * R);
  const double srr = sys.cylinder_force(0) / (2 * pi * R * L);
  return (szz + 2 * srr) / 3;
}

}  // namespace kolsky::dem
