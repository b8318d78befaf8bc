// The wall concept's motion, list upkeep, stable step and ledger (wall.hpp). One overload (or
// one branch of a visit) per shape: a new shape adds its own here.
#include "dem/wall.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/errors.hpp"

namespace kolsky::dem {

namespace {

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

// How far a profile moved since the list was built (m): a bound on the surface's shift.
double profile_shift(const FeProfile& p) {
  if (!p.now) return 0.0;
  const WallProfile& now = *p.now;
  const WallProfile& at_build = p.at_build;
  if (now.station.size() != at_build.station.size()) return std::numeric_limits<double>::infinity();
  // |offset change| at a fixed station <= max node change + slope x station change; the
  // slope of a bar face or tube wall is far below 1, so the station change counts fully.
  double d_offset = 0, d_station = 0;
  for (std::size_t k = 0; k < now.station.size(); ++k) {
    d_offset = std::max(d_offset, std::abs(now.offset[k] - at_build.offset[k]));
    d_station = std::max(d_station, std::abs(now.station[k] - at_build.station[k]));
  }
  return d_offset + d_station;
}

}  // namespace

Wall make_wall(const PlaneWall& w) {
  validate(w, "dem.walls.plane");
  Plane p;
  p.wall = w;
  return Wall{p};
}

Wall make_wall(const CylinderWall& w) {
  validate(w, "dem.walls.cylinder");
  Cylinder c;
  c.wall = w;
  if (w.compliance) {
    c.stiffness = w.compliance->radial_stiffness(w.radius);
    c.mass = w.compliance->radial_mass(w.radius);
  }
  return Wall{c};
}

const WallLaw& law_of(const Wall& w) {
  return std::visit([](const auto& s) -> const WallLaw& { return s.wall.law; }, w.shape);
}

void drive(Plane& p, double offset, double speed) {
  if (!std::holds_alternative<DrivenPlane>(p.wall.motion))
    throw InputError("", "dem.walls.plane", "drive_plane needs a DrivenPlane");
  p.offset = offset;
  p.speed = speed;
}

void drive_profile(Plane& p, WallProfile profile) {
  if (!std::holds_alternative<DrivenPlane>(p.wall.motion))
    throw InputError("", "dem.walls.plane", "drive_plane_profile needs a DrivenPlane");
  const Vec3& n = p.wall.normal;
  if (n.x != 0 || n.y != 0 || p.wall.point.x != 0 || p.wall.point.y != 0)
    throw InputError("", "dem.walls.plane", "a profiled plane must be normal to the z axis through it");
  validate(profile, "dem.walls.plane.profile");
  p.profile.now = std::move(profile);
}

void drive_profile(Cylinder& c, WallProfile profile) {
  if (c.wall.compliance)
    throw InputError("", "dem.walls.cylinder", "a driven cylinder has no compliance of its own");
  validate(profile, "dem.walls.cylinder.profile");
  c.profile.now = std::move(profile);
}

void kick(Wall& w, double half_dt) {
  if (auto* c = std::get_if<Cylinder>(&w.shape); c && c->mass > 0)
    c->u_dot += half_dt * (w.force - c->stiffness * c->u) / c->mass;
}

void drift(Wall& w, double t, double dt) {
  std::visit(Overloaded{[&](Plane& p) {
                          if (const auto* pr = std::get_if<PrescribedPlane>(&p.wall.motion)) {
                            p.offset += pr->velocity.displacement(t, t + dt);
                            p.speed = pr->velocity.at(t + dt);
                          }
                        },
                        [&](Cylinder& c) { c.u += dt * c.u_dot; }},
             w.shape);
}

void stop(Wall& w) {
  if (auto* c = std::get_if<Cylinder>(&w.shape)) c->u_dot = 0;
}

double moved_since_build(const Wall& w) {
  return std::visit(
      Overloaded{[](const Plane& p) { return std::abs(p.offset - p.offset_at_build) + profile_shift(p.profile); },
                 [](const Cylinder& c) { return std::abs(c.u - c.u_at_build) + profile_shift(c.profile); }},
      w.shape);
}

void mark_built(Wall& w) {
  std::visit(Overloaded{[](Plane& p) {
                          p.offset_at_build = p.offset;
                          if (p.profile.now) p.profile.at_build = *p.profile.now;
                        },
                        [](Cylinder& c) {
                          c.u_at_build = c.u;
                          if (c.profile.now) c.profile.at_build = *c.profile.now;
                        }},
             w.shape);
}

void record_force(Wall& w, double force) {
  if (auto* p = std::get_if<Plane>(&w.shape)) {
    // The profiled plane's owner books the interface work (docs/coupling.md).
    if (!p->profile.now) p->work += 0.5 * (w.force + force) * (p->offset - p->offset_at_force);
    p->offset_at_force = p->offset;
  }
  w.force = force;
}

double wall_stable_dt(const Wall& w, const LawLimits& limits) {
  double limit = std::visit([&](const auto& law) { return law.stable_dt(limits); }, law_of(w));
  if (const auto* c = std::get_if<Cylinder>(&w.shape); c && c->mass > 0)
    limit = std::min(limit, std::sqrt(c->mass / c->stiffness));  // the ring mode
  return limit;
}

WallEnergy energy_of(const Wall& w) {
  return std::visit(Overloaded{[](const Plane& p) { return WallEnergy{0.0, 0.0, p.work}; },
                               [](const Cylinder& c) {
                                 const double kinetic = 0.5 * c.mass * c.u_dot * c.u_dot;
                                 return WallEnergy{kinetic, 0.5 * c.stiffness * c.u * c.u, 0.0};
                               }},
                    w.shape);
}

bool is_finite(const Wall& w) {
  return std::visit(Overloaded{[&](const Plane& p) { return std::isfinite(p.offset) && std::isfinite(w.force); },
                               [](const Cylinder& c) { return std::isfinite(c.u) && std::isfinite(c.u_dot); }},
                    w.shape);
}

}  // namespace kolsky::dem
