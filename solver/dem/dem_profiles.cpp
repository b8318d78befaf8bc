// DemSystem's deformable walls (drive_plane_profile, drive_cylinder; dem_system.hpp): the
// surface and its velocity at a grain, and the rebuild bound of a moving profile. Used by the
// FE-DEM coupling (docs/coupling.md).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "dem/dem_system.hpp"

namespace kolsky::dem {

void DemSystem::drive_plane_profile(int plane, WallProfile profile) {
  PlaneState& s = planes_.at(plane);
  if (!std::holds_alternative<DrivenPlane>(s.wall.motion))
    throw InputError("", "dem.walls.plane", "drive_plane_profile needs a DrivenPlane");
  const Vec3& n = s.wall.normal;
  if (n.x != 0 || n.y != 0 || s.wall.point.x != 0 || s.wall.point.y != 0)
    throw InputError("", "dem.walls.plane", "a profiled plane must be normal to the z axis through it");
  validate(profile, "dem.walls.plane.profile");
  s.profile = std::move(profile);
}

void DemSystem::drive_cylinder(int cylinder, WallProfile profile) {
  TubeState& t = tubes_.at(cylinder);
  if (t.wall.compliance)
    throw InputError("", "dem.walls.cylinder", "a driven cylinder has no compliance of its own");
  validate(profile, "dem.walls.cylinder.profile");
  t.profile = std::move(profile);
}

double DemSystem::plane_offset_at(const PlaneState& s, const Vec3& x) {
  return s.profile ? s.profile->at(std::hypot(x.x, x.y)).offset : s.offset;
}

double DemSystem::tube_radius_at(const TubeState& t, const Vec3& x) {
  return t.wall.radius + t.u + (t.profile ? t.profile->at(x.z).offset : 0.0);
}

Vec3 DemSystem::plane_velocity_at(const PlaneState& s, const Vec3& x) {
  if (!s.profile) return s.speed * s.wall.normal;
  const double rho = std::hypot(x.x, x.y);
  const WallProfile::Sample a = s.profile->at(rho);
  const Vec3 e_rho = rho > 0 ? Vec3{x.x / rho, x.y / rho, 0} : Vec3{};
  return a.normal_speed * s.wall.normal + a.tangential_speed * e_rho;
}

Vec3 DemSystem::tube_velocity_at(const TubeState& t, const Vec3& x, const Vec3& n) {
  if (!t.profile) return t.u_dot * n;
  const WallProfile::Sample a = t.profile->at(x.z);
  return (t.u_dot + a.normal_speed) * n + Vec3{0, 0, a.tangential_speed};
}

double DemSystem::profile_shift(const std::optional<WallProfile>& now, const WallProfile& at_build) {
  if (!now) return 0.0;
  if (now->station.size() != at_build.station.size()) return std::numeric_limits<double>::infinity();
  // |offset change| at a fixed station <= max node change + slope x station change; the
  // slope of a bar face or tube wall is far below 1, so the station change counts fully.
  double d_offset = 0, d_station = 0;
  for (std::size_t k = 0; k < now->station.size(); ++k) {
    d_offset = std::max(d_offset, std::abs(now->offset[k] - at_build.offset[k]));
    d_station = std::max(d_station, std::abs(now->station[k] - at_build.station[k]));
  }
  return d_offset + d_station;
}

}  // namespace kolsky::dem
