// The benchmark compaction scene of ../shared/bench/README.md, shared by bench_dem
// (BM_DemCompaction and the breakage cases), dem_agreement (forces at fixed steps, compared
// with LAMMPS and LIGGGHTS in lammps/agreement.sh) and the in-test check
// verification/test_dem_peer_reference.cpp (a cut of the packing against a LAMMPS reference).
// One definition, so that the timed scene, the compared scene and the tested scene cannot drift
// apart: Hertz-Mindlin E = 78 GPa (G = 30 GPa), nu = 0.3, mu = 0.5 with rigid Hertz walls too,
// e = 0.5, no gravity, a tube around z, a fixed bottom plane at z = 0 and a lid at `top` moving
// down at 9.3 m/s from the first step; dt = 0.25 x the Rayleigh step of the smallest grain.
#pragma once
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "dem/contact_hertz_mindlin.hpp"
#include "dem/dem_system.hpp"
#include "dem/spatial_sort.hpp"

namespace kolsky::bench {

struct Specimen {
  dem::Particles particles;
  double density = 2650, radius = 0.00955, top = 0.0085;
  std::string label;  ///< which packing (shown in the benchmark's output and JSON)
};

/// The shared packing beside the repository (CI and the development machines have ../shared).
inline std::string shared_pack_path() {
  return std::string(KOLSKY_SOURCE_DIR) + "/../shared/bench/pack_35k.data.gz";
}

// LAMMPS atomic-sphere data through `gzip -dc`: after the "Atoms" line, `id type diameter
// density x y z`. Keeps the grains whose top z + r lies at or below `z_top_max` (all by
// default; a cut of the packing for a short check). Returns false when the file is absent or
// unreadable or nothing is kept.
inline bool read_pack(const std::string& path, Specimen& s,
                      double z_top_max = std::numeric_limits<double>::infinity()) {
  if (!std::filesystem::exists(path)) return false;
  FILE* pipe = popen(("gzip -dc '" + path + "'").c_str(), "r");
  if (!pipe) return false;
  std::string text;
  char buf[1 << 16];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) text.append(buf, n);
  if (pclose(pipe) != 0) return false;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line) && line.rfind("Atoms", 0) != 0) {
  }
  const std::vector<dem::Material> tmp{dem::Material{78e9, 0.3, 2650}};
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    long id = 0;
    int type = 0;
    double d = 0, rho = 0, x = 0, y = 0, z = 0;
    if (!(ls >> id >> type >> d >> rho >> x >> y >> z)) continue;
    if (z + d / 2 > z_top_max) continue;
    s.density = rho;
    s.particles.add({x, y, z}, d / 2, 0, tmp);
  }
  // The file lists grains largest first, in random places; order them cell by cell (LAMMPS
  // sorts its atoms too by default, atom_modify sort) so contact partners sit close in
  // memory: along the Morton curve of cells of the smallest diameter, which keeps partners in
  // all three directions near (12 % of the listed pairs cross a 2048-grain owner block and
  // 8 % lie over 1365 grains apart, against 19 % and 17 % for sort_spatially's rows of 1.2 mm
  // cells; docs/dem.md, "Performance").
  double d_min = std::numeric_limits<double>::infinity();
  for (double r : s.particles.radius) d_min = std::min(d_min, 2 * r);
  if (s.particles.size() > 0) dem::sort_morton(s.particles, d_min);
  return s.particles.size() > 0;
}

struct Scene {
  std::unique_ptr<dem::DemSystem> sys;
  double dt = 0;
};

// Wall indices of make_scene: planes 0 (bottom) and 1 (lid), cylinder 0 (tube).
inline constexpr int kBottomPlane = 0, kLidPlane = 1, kTube = 0;

// opt.smallest_radius_to_come > 0 (breakage): dt from that radius, as a breaking run steps.
inline Scene make_scene(const Specimen& s, const dem::DemOptions& opt = {}) {
  const dem::Material m{78e9, 0.3, s.density};  // G = E / (2 (1 + nu)) = 30 GPa
  const std::vector<dem::Material> materials{m};
  const dem::HertzMindlinParams hm{0.5, 0.5};
  dem::Material rigid = m;
  rigid.youngs_modulus = std::numeric_limits<double>::infinity();
  const dem::HertzMindlinWall wall(materials, rigid, hm);
  dem::Particles p = s.particles;
  double r_min = p.radius[0];
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.material[i] = 0;
    r_min = std::min(r_min, p.radius[i]);
  }
  // add() used a placeholder density for the pack file; recompute with the scene's.
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = p.radius[i];
    p.mass[i] = 4.0 / 3.0 * 3.141592653589793 * r * r * r * s.density;
    p.inertia[i] = 0.4 * p.mass[i] * r * r;
  }
  Scene sc;
  sc.sys = std::make_unique<dem::DemSystem>(std::move(p), materials, dem::HertzMindlin(materials, hm), opt);
  sc.sys->add_cylinder(dem::CylinderWall{0, 0, s.radius, std::nullopt, wall});
  sc.sys->add_plane(dem::PlaneWall{{0, 0, 0}, {0, 0, 1}, dem::FixedPlane{}, wall});
  sc.sys->add_plane(dem::PlaneWall{{0, 0, s.top}, {0, 0, -1},
                                   dem::PrescribedPlane{dem::VelocityHistory{{0.0}, {9.3}}}, wall});
  if (opt.smallest_radius_to_come > 0) r_min = std::min(r_min, opt.smallest_radius_to_come);
  sc.dt = 0.25 * dem::rayleigh_time_step(r_min, m);
  return sc;
}

/// What the peers print at a step (magnitudes, N): the lid's and the bottom's normal contact
/// forces (elastic + dashpot), the tube's total radial contact force, and the mean grain-grain
/// coordination 2 x touching pairs / grains (rattlers included, as LAMMPS' and LIGGGHTS'
/// compute contact/atom averaged over all atoms).
struct PeerQuantities {
  double lid_force = 0, bottom_force = 0, tube_force = 0, coordination = 0;
};

inline PeerQuantities peer_quantities(const dem::DemSystem& sys) {
  PeerQuantities q;
  q.lid_force = sys.plane_force(kLidPlane);
  q.bottom_force = sys.plane_force(kBottomPlane);
  q.tube_force = sys.cylinder_force(kTube);
  q.coordination = 2.0 * static_cast<double>(sys.n_contacts()) /
                   static_cast<double>(sys.particles().size());
  return q;
}

}  // namespace kolsky::bench
