// Internals shared by the packing files (packing.cpp: generation; packing_census.cpp: the
// census of a finished packing; prestress.cpp; wall_layer.cpp; servo_compaction.cpp): a uniform
// cell grid over the packing cylinder, the progress hook, and the jammed packings' law, density
// scaling and rotation lock.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "dem/contact_linear.hpp"
#include "dem/dem_system.hpp"
#include "dem/packing.hpp"

namespace kolsky::dem {

// Reports p through in.on_progress, when one is set.
inline void progress(const PackingParams& in, const PackingProgress& p) {
  if (in.on_progress) in.on_progress(p);
}

// Uniform cell grid over the cylinder's bounding box [-R, R]^2 x [0, L].
struct CellGrid {
  double cell, R, L;
  int nx, nz;
  std::vector<std::vector<int>> cells;

  CellGrid(double cell_size, double radius, double length)
      : cell(cell_size), R(radius), L(length) {
    nx = std::max(1, static_cast<int>(2 * R / cell) + 1);
    nz = std::max(1, static_cast<int>(L / cell) + 1);
    cells.resize(static_cast<std::size_t>(nx) * nx * nz);
  }
  int ix(double u) const { return std::clamp(static_cast<int>((u + R) / cell), 0, nx - 1); }
  int iz(double u) const { return std::clamp(static_cast<int>(u / cell), 0, nz - 1); }
  std::vector<int>& at(int x, int y, int z) {
    return cells[(static_cast<std::size_t>(z) * nx + y) * nx + x];
  }
  void insert(const Vec3& c, int id) { at(ix(c.x), ix(c.y), iz(c.z)).push_back(id); }
  // Calls f(q) for every id in the 27 cells around c; stops when f returns false.
  template <class F> bool visit(const Vec3& c, F&& f) {
    const int cx = ix(c.x), cy = ix(c.y), cz = iz(c.z);
    for (int z = std::max(0, cz - 1); z <= std::min(nz - 1, cz + 1); ++z)
      for (int y = std::max(0, cy - 1); y <= std::min(nx - 1, cy + 1); ++y)
        for (int x = std::max(0, cx - 1); x <= std::min(nx - 1, cx + 1); ++x)
          for (int q : at(x, y, z))
            if (!f(q)) return false;
    return true;
  }
};

// mass_floor > 0: density scaling (jam and servo-wall stages): no grain lighter than mass_floor.
inline void set_radius(Particles& p, std::size_t i, double r, double rho, double mass_floor = 0) {
  p.radius[i] = r;
  p.mass[i] = std::max(sphere_mass(r, rho), mass_floor);
  p.inertia[i] = 0.4 * p.mass[i] * r * r;
}

// The frictional linear law of the jammed and servo-wall packings: Hertz secant stiffness
// between two mean grains at the design overlap (E* = E / (2(1 - nu^2)), R* = r/2), k_s = 2/7
// k_n (the tangential mode of a sphere, effective mass m/3.5, then has the normal mode's
// frequency, so friction does not lower the stable step).
inline LinearSpring jam_law(const PackingParams& in, double mean_r, double friction) {
  const double E = in.material.youngs_modulus, nu = in.material.poisson_ratio;
  const double e_star = E / (2 * (1 - nu * nu));
  const double delta_t = in.jam_overlap * mean_r;
  const double k = 4.0 / 3.0 * e_star * std::sqrt(0.5 * mean_r * delta_t);
  return linear_spring(k, 2.0 / 7.0 * k, friction, in.damping_ratio, in.damping_ratio);
}

// Density scaling: the packing's end state is a static equilibrium, which does not depend on
// the masses, while the step does (sqrt(m_min / k)); the mean grain's mass as a floor raises
// the step by sqrt(m_mean / m_min), ~5x for the Song curve (docs/dem.md, "Packing"). 0: off.
inline double jam_mass_floor(const PackingParams& in, const std::vector<double>& target) {
  if (!in.jam_mass_scaling) return 0;
  double floor = 0;
  for (double r : target) floor += sphere_mass(r, in.material.density);
  return floor / static_cast<double>(target.size());
}

// Rotation locked while packing (packing_lock_rotation): k = 0 of Eqs. 4.12-4.14.
inline DemOptions packing_options(const PackingParams& in) {
  DemOptions o;
  if (in.packing_lock_rotation) o.rolling.factor_per_reference_step = 0;
  return o;
}

/// Initial length of the servo-wall packing's cylinder: the grains are placed at full size at
/// initial_solid_fraction, then the end walls close to `length` (servo_compaction.cpp).
inline double servo_initial_length(const PackingParams& in) {
  return in.length * (1 - in.porosity) / in.initial_solid_fraction;
}

/// Servo-wall compaction of the placed grains (p at full size in the initial length; target:
/// their radii) to the cylinder's length, then quenched settling (servo_compaction.cpp).
void servo_wall_stage(const PackingParams& in, Particles p, const std::vector<double>& target,
                      double mean_r, PackingResult& res);

/// Census of the final state (coordination with and without walls and rattlers, largest
/// overlap, Hertz contact-virial stress), grains put at rest with the requested material
/// index, porosity from the final radii (packing_census.cpp).
void take_census(PackingResult& res, const PackingParams& in);

}  // namespace kolsky::dem
