// A DEM scene with every mechanism on, shared by the thread-determinism and restart tests: a
// slightly overlapping jittered cubic lattice of grains (radii r (1 - 0.02 (i mod 5)), random
// velocities, spin) inside a compliant tube between a fixed plane and a plane pushed in at
// 10 m/s; Hertz-Mindlin with friction 0.5 and restitution 0.5, Table 4.1 linear tube contact,
// rolling retardation, and a small Verlet skin so a short run rebuilds its lists several times.
#pragma once
#include <cmath>
#include <vector>

#include "dem/contact_hertz_mindlin.hpp"
#include "dem/dem_system.hpp"
#include "dem/test_fills.hpp"

namespace kolsky::dem::test {

inline const std::vector<Material> kBusySand{{78e9, 0.3, 2650}};

struct BusyScene {
  int cells = 9;               ///< lattice cells per side (odd: centred on the axis)
  double tube_radius = 1.3e-3;  ///< m
  double tube_wall = 2e-4;      ///< tube wall thickness, m
  double speed = 3.0;           ///< scale of the random initial velocities, m/s
  double r = 1.5e-4;            ///< grain radius before the jitter, m
  double spacing() const { return 2 * r * 0.999; }
  double top() const { return cells * spacing() + r; }
};

inline Particles busy_grains(const BusyScene& s) {
  const double a = s.spacing(), c = -(s.cells - 1) / 2 * a;
  const Particles lat = cubic_lattice(s.cells, s.cells, s.cells, s.r, a, {c, c, s.r}, 0, kBusySand);
  Particles p;
  for (std::size_t i = 0; i < lat.size(); ++i)
    if (std::hypot(lat.x[i].x, lat.x[i].y) < s.tube_radius - s.r)
      p.add(lat.x[i], s.r * (1 - 0.02 * static_cast<double>(i % 5)), 0, kBusySand);
  randomize_velocities(p, s.speed, 5);
  for (auto& w : p.omega) w = {1e3, -2e3, 5e2};
  return p;
}

inline DemOptions busy_options() {
  DemOptions opt;
  opt.rolling.factor_per_reference_step = 0.99999975;
  opt.skin_over_min_radius = 0.1;  // small skin: forces several rebuilds in a short run
  // The caller's thread count at every step, so a run said to use two threads does (the
  // thread governor would move a loaded machine's run to one: test_thread_governor.cpp).
  opt.adapt_threads = false;
  return opt;
}

inline DemSystem busy_system(const BusyScene& s, const DemOptions& opt = busy_options()) {
  const HertzMindlinParams hp{0.5, 0.5};
  DemSystem sys(busy_grains(s), kBusySand, HertzMindlin(kBusySand, hp), opt);
  const WallLaw hw = HertzMindlinWall(kBusySand, kBusySand[0], hp);
  sys.add_plane({{0, 0, 0}, {0, 0, 1}, FixedPlane{}, hw});
  sys.add_plane({{0, 0, s.top()}, {0, 0, -1}, PrescribedPlane{{{0.0}, {10.0}}}, hw});
  CylinderWall tube;
  tube.radius = s.tube_radius;
  tube.law = linear_spring(2.6e6, 1.6e6, 0.3);
  tube.compliance = TubeCompliance{200e9, s.tube_wall, 8100, s.top()};
  sys.add_cylinder(tube);
  return sys;
}

}  // namespace kolsky::dem::test
