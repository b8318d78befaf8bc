// Servo-wall compaction (docs/dem.md, "Packing", procedure servo_walls): the usual way PFC3D and
// LIGGGHTS users bring a frictional assembly to a porosity looser than random close packing.
// The grains, placed at full size in a cylinder long enough for initial_solid_fraction
// (servo_initial_length), are compacted by the two end walls closing symmetrically on the
// cylinder's length, under the jammed packing's frictional linear law (mu_pack = jam_friction,
// frictionless walls, density scaling and the rotation lock as set), then settle at the final
// length with v = omega = 0 at every stage until the largest overlap is below the tolerance.
// The walls close at a constant speed over growth_stages stages of jam_steps_per_stage steps,
// with the velocities quenched at every stage: the growth's schedule, so both procedures take
// the same number of steps to the target porosity. Symmetric closing keeps the density
// gradient of a one-sided compaction out of the specimen. SI units.
#include <algorithm>
#include <cmath>
#include <vector>

#include "dem/packing_internal.hpp"
#include "dem/packing_walls.hpp"
#include "dem/walls.hpp"

namespace kolsky::dem {

void servo_wall_stage(const PackingParams& in, Particles p, const std::vector<double>& target,
                      double mean_r, PackingResult& res) {
  const double R = in.diameter / 2, L = in.length, L0 = servo_initial_length(in);
  const double travel = 0.5 * (L0 - L);  // each end wall's, m
  const double n = static_cast<double>(target.size());
  const double mass_floor = jam_mass_floor(in, target);
  for (std::size_t i = 0; i < p.size(); ++i) set_radius(p, i, p.radius[i], in.material.density, mass_floor);
  const std::vector<Material> materials{in.material};
  DemSystem sys(std::move(p), materials, jam_law(in, mean_r, in.jam_friction), packing_options(in));
  // Frictionless walls, as in the jammed growth: wall friction would hold the wall zone looser.
  const LinearSpring wall = jam_law(in, mean_r, 0.0);
  // Cylinder 0, then planes 0 and 1: the indices wall_mean_stress (packing_walls.hpp) reads.
  sys.add_cylinder(CylinderWall{0, 0, R, std::nullopt, wall});
  const int bottom = sys.add_plane(PlaneWall{{0, 0, 0}, {0, 0, 1}, DrivenPlane{}, wall});
  const int top = sys.add_plane(PlaneWall{{0, 0, L0}, {0, 0, -1}, DrivenPlane{}, wall});
  const double dt = kDemStepFraction * sys.stable_dt();
  const int sps = in.jam_steps_per_stage, stages = in.growth_stages;
  const double speed = travel / (static_cast<double>(stages) * sps * dt);
  double offset = 0;
  auto drive = [&](double v) {
    sys.drive_plane(bottom, offset, v);
    sys.drive_plane(top, offset, v);
  };
  auto quench = [&](double f) {
    Particles& q = sys.mutable_particles();
    for (std::size_t i = 0; i < q.size(); ++i) {
      q.v[i] = f * q.v[i];
      q.omega[i] = f * q.omega[i];
    }
  };
  auto report = [&](const char* phase, int done, int most, double value) {
    if (!in.on_progress) return;
    PackingProgress q{phase, done, most, value};
    q.wall_stress = wall_mean_stress(sys, R, L0 - 2 * offset);  // over the current gap
    q.coordination = 2.0 * static_cast<double>(sys.n_contacts()) / n;
    const DemEnergy e = sys.energy();
    q.kinetic_to_elastic = e.kinetic / std::max(e.elastic, 1e-300);
    progress(in, q);
  };
  for (int g = 1; g <= stages; ++g) {
    quench(in.jam_velocity_quench);
    for (int j = 0; j < sps; ++j) {
      offset = std::min(travel, offset + speed * dt);
      drive(speed);
      sys.step(dt);
    }
    res.steps += sps;
    ++res.stages;
    report("compaction", g, stages, (L0 - 2 * offset) / L);
  }
  offset = travel;
  drive(0.0);
  // The largest overlap with the walls where they now stand (the census's planes are 0 and L).
  auto overlap_now = [&] {
    Particles q = sys.particles();
    for (Vec3& x : q.x) x.z -= travel;
    return max_packing_overlap(q, in.diameter, L) / mean_r;
  };
  double overlap = overlap_now();
  for (int k = 0; k < in.max_settle_stages && overlap >= in.overlap_tolerance; ++k) {
    quench(0.0);
    for (int j = 0; j < sps; ++j) sys.step(dt);
    res.steps += sps;
    ++res.stages;
    overlap = overlap_now();
    report("settle", k + 1, in.max_settle_stages, overlap);
  }
  res.packing_friction = in.jam_friction;
  res.kinetic_energy = sys.particles().kinetic_energy();
  sys.compute_forces();
  res.mean_stress = wall_mean_stress(sys, R, L);
  res.particles = sys.particles();
  for (std::size_t i = 0; i < res.particles.size(); ++i) {  // between z = 0 and L, own masses
    res.particles.x[i].z -= travel;
    set_radius(res.particles, i, res.particles.radius[i], in.material.density);
  }
  res.settled = overlap < in.overlap_tolerance;
}

}  // namespace kolsky::dem
