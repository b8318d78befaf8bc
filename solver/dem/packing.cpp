// Packing generator: sample, place small (RSA), grow with damped frictionless contacts, settle
// (see packing.hpp).
#include "dem/packing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dem/assembly.hpp"
#include "dem/contact_linear.hpp"
#include "dem/dem_system.hpp"
#include "psd/sampling.hpp"

namespace kolsky::dem {

namespace {

constexpr double kPi = std::numbers::pi;

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

void check(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) throw InputError("", "dem.packing." + field, rule);
}

void set_radius(Particles& p, std::size_t i, double r, double rho) {
  p.radius[i] = r;
  p.mass[i] = 4.0 / 3.0 * kPi * r * r * r * rho;
  p.inertia[i] = 0.4 * p.mass[i] * r * r;
}

}  // namespace

double max_packing_overlap(const Particles& p, double diameter, double length) {
  const double R = diameter / 2;
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  double worst = 0;
  if (p.size() == 0) return 0;
  CellGrid grid(2 * r_max, R, length);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& c = p.x[i];
    const double r = p.radius[i];
    worst = std::max({worst, r - c.z, c.z + r - length, std::hypot(c.x, c.y) + r - R});
    grid.visit(c, [&](int q) {
      const double d = r + p.radius[q];
      const double dist2 = norm2(p.x[q] - c);
      if (dist2 < d * d) worst = std::max(worst, d - std::sqrt(dist2));
      return true;
    });
    grid.insert(c, static_cast<int>(i));
  }
  return worst;
}

PackingResult generate_packing(const PackingParams& in) {
  in.curve.validate();
  check(in.porosity > 0 && in.porosity < 1, "porosity", "must be in (0, 1)");
  check(in.diameter > 0 && std::isfinite(in.diameter), "diameter", "must be finite and > 0");
  check(in.length > 0 && std::isfinite(in.length), "length", "must be finite and > 0");
  check(in.initial_solid_fraction > 0 && in.initial_solid_fraction < 1 - in.porosity,
        "initial_solid_fraction", "must be in (0, 1 - porosity)");
  check(in.growth_stages >= 1, "growth_stages", "must be >= 1");
  check(in.steps_per_stage >= 1, "steps_per_stage", "must be >= 1");
  check(in.velocity_quench >= 0 && in.velocity_quench <= 1, "velocity_quench",
        "must be in [0, 1]");
  check(in.damping_ratio >= 0 && in.damping_ratio < 1, "damping_ratio", "must be in [0, 1)");
  check(in.overlap_tolerance > 0, "overlap_tolerance", "must be > 0");
  check(in.max_settle_stages >= 0, "max_settle_stages", "must be >= 0");
  check(in.material_index >= 0, "material_index", "must be >= 0");
  const std::vector<Material> materials{in.material};
  validate(materials);

  const double R = in.diameter / 2, L = in.length;
  const double volume = psd::cylinder_volume(in.diameter, L);
  const std::vector<double> d = psd::sample_diameters(in.curve, volume * (1 - in.porosity),
                                                      in.seed);
  check(2 * d.front() < std::min(in.diameter, L), "curve",
        "largest grain does not fit twice across the cylinder");

  PackingResult res;
  res.target_porosity = in.porosity;
  res.expected_count = psd::expected_particle_count(in.curve, volume, in.porosity);
  res.curve_deviation = psd::max_passing_deviation(in.curve, d);
  res.curve_deviation_bound = psd::max_passing_deviation_bound(in.curve, volume * (1 - in.porosity));

  // 2. RSA of the shrunk spheres, largest first.
  const double s0 = std::cbrt(in.initial_solid_fraction / (1 - in.porosity));
  Xoshiro256ss rng(in.seed ^ 0x5deece66dULL);
  Particles p;
  p.reserve(d.size());
  std::vector<double> target;  // full radius, in particle order
  target.reserve(d.size());
  {
    CellGrid grid(s0 * d.front(), R, L);
    for (std::size_t s = 0; s < d.size(); ++s) {
      const double r = s0 * d[s] / 2;
      bool placed = false;
      for (int attempt = 0; attempt < in.max_rsa_attempts && !placed; ++attempt) {
        const double rho = (R - r) * std::sqrt(rng.uniform_open());
        const double phi = 2 * kPi * rng.uniform_open();
        const Vec3 c{rho * std::cos(phi), rho * std::sin(phi), r + (L - 2 * r) * rng.uniform_open()};
        const bool free = grid.visit(c, [&](int q) {
          const double dd = r + p.radius[q];
          return norm2(p.x[q] - c) >= dd * dd;
        });
        if (!free) continue;
        grid.insert(c, static_cast<int>(p.size()));
        p.add(c, r, 0, materials);
        target.push_back(d[s] / 2);
        placed = true;
      }
      check(placed, "initial_solid_fraction",
            "random sequential addition found no place for grain " + std::to_string(s) +
                " after " + std::to_string(in.max_rsa_attempts) + " tries; lower it");
    }
  }
  // Spatial order for memory locality; the target radii follow the permutation.
  {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) p.f[i] = {target[i], 0, 0};  // carry target through
    sort_spatially(p, s0 * d.front());
    for (std::size_t i = 0; i < n; ++i) {
      target[i] = p.f[i].x;
      p.f[i] = {};
    }
  }

  // 3. growth with frictionless, damped linear contacts (grains and rigid walls). Linear, not
  // Hertz: a Hertz contact softens as the overlap vanishes, so the last overlaps would relax
  // ever more slowly. The stiffness only sets the time scale (the step follows it).
  double mean_r = 0;
  for (double r : target) mean_r += r;
  mean_r /= static_cast<double>(target.size());
  const LinearSpring law = linear_spring(in.material.youngs_modulus * mean_r, 0.0, 0.0,
                                         in.damping_ratio, 0.0);
  DemOptions opt;
  DemSystem sys(std::move(p), materials, law, opt);
  sys.add_cylinder(CylinderWall{0, 0, R, std::nullopt, law});
  sys.add_plane(PlaneWall{{0, 0, 0}, {0, 0, 1}, FixedPlane{}, law});
  sys.add_plane(PlaneWall{{0, 0, L}, {0, 0, -1}, FixedPlane{}, law});
  // The lightest grain only grows, so the step of the shrunk state stays stable throughout.
  const double dt = sys.stable_dt();
  const double rho = in.material.density;

  auto stage = [&](double scale) {
    Particles& q = sys.mutable_particles();
    for (std::size_t i = 0; i < q.size(); ++i) {
      set_radius(q, i, scale * target[i], rho);
      q.v[i] = in.velocity_quench * q.v[i];
      q.omega[i] = in.velocity_quench * q.omega[i];
    }
    for (int k = 0; k < in.steps_per_stage; ++k) sys.step(dt);
    res.steps += in.steps_per_stage;
  };
  for (int g = 1; g <= in.growth_stages; ++g)
    stage(s0 + (1 - s0) * static_cast<double>(g) / in.growth_stages);

  // 4. settling at full size.
  double overlap = max_packing_overlap(sys.particles(), in.diameter, L) / mean_r;
  for (int k = 0; k < in.max_settle_stages && overlap >= in.overlap_tolerance; ++k) {
    stage(1.0);
    overlap = max_packing_overlap(sys.particles(), in.diameter, L) / mean_r;
  }
  res.settled = overlap < in.overlap_tolerance;
  res.max_overlap = overlap;
  res.kinetic_energy = sys.particles().kinetic_energy();
  sys.compute_forces();
  res.coordination = 2.0 * static_cast<double>(sys.n_contacts()) / static_cast<double>(target.size());
  res.coordination_with_walls =
      (2.0 * static_cast<double>(sys.n_contacts()) + static_cast<double>(sys.n_wall_contacts())) /
      static_cast<double>(target.size());

  res.particles = sys.particles();
  Particles& out = res.particles;
  double solid = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    out.v[i] = {};
    out.omega[i] = {};
    out.f[i] = {};
    out.torque[i] = {};
    out.material[i] = in.material_index;
    solid += 4.0 / 3.0 * kPi * std::pow(out.radius[i], 3);
  }
  res.count = out.size();
  res.porosity = 1 - solid / volume;
  return res;
}

}  // namespace kolsky::dem
