// One wall concept for a DEM assembly. Every wall answers the same three questions at a point,
// whatever its shape: the gap to a grain there, the unit normal from the grain towards the
// wall, and the wall's velocity there (as LAMMPS's fix wall/gran asks its wall styles,
// https://docs.lammps.org/fix_wall_gran.html). The shapes are a variant: a plane moving along
// its normal and the inner surface of a z-parallel cylinder (the confining tube, rigid or a
// one-DOF elastic ring, walls.hpp); either may carry an FE profile, a deformed shape set from
// outside each step (the FE-DEM coupling, docs/coupling.md). A new shape is a new alternative
// and its overloads here and in wall.cpp: the force kernel, the candidate lists, edits and the
// contact visit (contact_forces.cpp, contact_network.*, particle_edit.cpp) only call the
// free functions. Walls are global: every MPI rank will hold all of them (a few per specimen).
//
// Round-off: gap_at is written so that -gap_at is bitwise the overlap the force kernels have
// always computed (r - dot(x - base, n) for a plane; r + rho - R for a cylinder): IEEE
// rounding is symmetric, so a - b = -(b - a) exactly. SI units.
#pragma once
#include <cmath>
#include <optional>
#include <variant>

#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"
#include "dem/walls.hpp"

namespace kolsky::dem {

/// An FE surface's shape laid over a wall (DemSystem::drive_plane_profile, drive_cylinder):
/// the profile now (none: the wall's own shape) and at the last list rebuild.
struct FeProfile {
  std::optional<WallProfile> now;
  WallProfile at_build;
};

/// A plane as the assembly moves it. Profile stations: the distance from the z axis.
struct Plane {
  PlaneWall wall;
  double offset = 0, speed = 0;  ///< along the normal (m, m/s)
  double offset_at_build = 0;    ///< at the last list rebuild, m
  double offset_at_force = 0;    ///< at the last force evaluation (the work's trapezoid), m
  double work = 0;               ///< done on the grains, J (left out for a profiled plane)
  FeProfile profile;
};

/// A cylinder's inner surface as the assembly moves it: the radial displacement u of its ring
/// mode (zero stiffness and mass: rigid). Profile stations: z.
struct Cylinder {
  CylinderWall wall;
  double u = 0, u_dot = 0, u_at_build = 0;  ///< m, m/s, m
  double stiffness = 0, mass = 0;           ///< TubeCompliance: N/m, kg
  FeProfile profile;
};

using WallShape = std::variant<Plane, Cylinder>;

struct Wall {
  WallShape shape;
  /// Total normal contact force of the last evaluation, N: a plane's compression +, a
  /// cylinder's outward radial force +.
  double force = 0;
};

/// Throws kolsky::InputError (dem.walls.plane / dem.walls.cylinder) for a degenerate wall.
Wall make_wall(const PlaneWall& w);
Wall make_wall(const CylinderWall& w);

// --- The three questions (and the curvature the Hertz laws need), per shape. Inline: the
// force kernel calls them once per wall contact.

/// Gap between the wall and a grain of radius r centred at x (m; < 0: overlap).
inline double gap_at(const Plane& p, const Vec3& x, double r) {
  const Vec3& n = p.wall.normal;
  if (p.profile.now) return (dot(x - p.wall.point, n) - r) - p.profile.now->at(std::hypot(x.x, x.y)).offset;
  const Vec3 base = p.wall.point + p.offset * n;
  return dot(x - base, n) - r;
}
/// The cylinder's surface radius at x (its profile at x.z, if driven).
inline double surface_radius_at(const Cylinder& c, const Vec3& x) {
  return c.wall.radius + c.u + (c.profile.now ? c.profile.now->at(x.z).offset : 0.0);
}
inline double axis_distance(const Cylinder& c, const Vec3& x) {
  const double dx = x.x - c.wall.cx, dy = x.y - c.wall.cy;
  return std::sqrt(dx * dx + dy * dy);
}
inline double gap_at(const Cylinder& c, const Vec3& x, double r) {
  return surface_radius_at(c, x) - (r + axis_distance(c, x));
}

/// Unit normal from a grain at x towards the wall (the contact laws' n).
inline Vec3 normal_at(const Plane& p, const Vec3&) { return -p.wall.normal; }
inline Vec3 normal_at(const Cylinder& c, const Vec3& x) {
  const double dx = x.x - c.wall.cx, dy = x.y - c.wall.cy;
  const double rho = std::sqrt(dx * dx + dy * dy);
  return rho > 0 ? Vec3{dx / rho, dy / rho, 0} : Vec3{1, 0, 0};
}

/// Velocity of the wall's surface at x (m/s): a profile's normal and tangential speeds at the
/// station of x, else the plane's speed or the ring's radial speed.
inline Vec3 velocity_at(const Plane& p, const Vec3& x) {
  if (!p.profile.now) return p.speed * p.wall.normal;
  const double rho = std::hypot(x.x, x.y);
  const WallProfile::Sample a = p.profile.now->at(rho);
  const Vec3 e_rho = rho > 0 ? Vec3{x.x / rho, x.y / rho, 0} : Vec3{};
  return a.normal_speed * p.wall.normal + a.tangential_speed * e_rho;
}
inline Vec3 velocity_at(const Cylinder& c, const Vec3& x) {
  const Vec3 n = normal_at(c, x);
  if (!c.profile.now) return c.u_dot * n;
  const WallProfile::Sample a = c.profile.now->at(x.z);
  return (c.u_dot + a.normal_speed) * n + Vec3{0, 0, a.tangential_speed};
}

/// R* of a grain of radius r against the wall at x: r for a plane; for the concave inner
/// surface of radius R, r R / (R - r): the relative curvature 1/r - 1/R of a sphere in a
/// concave seat (Johnson, Contact Mechanics, 1985, Ch. 4). Only Hertz laws read it.
inline double contact_radius_at(const Plane&, const Vec3&, double r) { return r; }
inline double contact_radius_at(const Cylinder& c, const Vec3& x, double r) {
  const double radius = surface_radius_at(c, x);
  return radius > r ? r * radius / (radius - r) : r;
}

// --- The same over any wall (one visit per call: for the loops outside the force kernel).
inline double gap_at(const Wall& w, const Vec3& x, double r) {
  return std::visit([&](const auto& s) { return gap_at(s, x, r); }, w.shape);
}
inline Vec3 normal_at(const Wall& w, const Vec3& x) {
  return std::visit([&](const auto& s) { return normal_at(s, x); }, w.shape);
}
inline Vec3 velocity_at(const Wall& w, const Vec3& x) {
  return std::visit([&](const auto& s) { return velocity_at(s, x); }, w.shape);
}
inline double contact_radius_at(const Wall& w, const Vec3& x, double r) {
  return std::visit([&](const auto& s) { return contact_radius_at(s, x, r); }, w.shape);
}
const WallLaw& law_of(const Wall& w);

// --- Motion between steps (DemSystem's kick-drift-kick and list upkeep).

/// Sets a DrivenPlane's offset (m) and speed (m/s). Throws InputError for another motion.
void drive(Plane& p, double offset, double speed);
/// Gives the wall an FE profile (walls.hpp, WallProfile). A plane must be a DrivenPlane normal
/// to z through the axis; a cylinder must be rigid. Throws InputError.
void drive_profile(Plane& p, WallProfile profile);
void drive_profile(Cylinder& c, WallProfile profile);
/// Half kick of a compliant ring by the last contact force (no-op otherwise), s.
void kick(Wall& w, double half_dt);
/// Drift over [t, t + dt]: a PrescribedPlane follows its velocity history exactly; a ring
/// moves by dt u_dot.
void drift(Wall& w, double t, double dt);
/// Stops a ring's radial motion (DemSystem::stop_grains).
void stop(Wall& w);
/// How far the surface may have moved since the last list rebuild (m): an upper bound.
double moved_since_build(const Wall& w);
/// Records the current position as the one of the list rebuild.
void mark_built(Wall& w);
/// Stores the resultant of this evaluation (N); a plane without profile adds its work on the
/// grains by the trapezoid rule over its displacement since the last evaluation.
void record_force(Wall& w, double force);

/// Largest stable dt of the wall (s): its law's limit and a ring's sqrt(m/K).
double wall_stable_dt(const Wall& w, const LawLimits& limits);
/// What the wall holds in the energy ledger (J): a ring's kinetic and elastic energy, a
/// plane's work on the grains; zero for the rest.
struct WallEnergy {
  double kinetic = 0, elastic = 0, work = 0;
};
WallEnergy energy_of(const Wall& w);
bool is_finite(const Wall& w);

}  // namespace kolsky::dem
