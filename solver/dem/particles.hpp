// DEM spheres as a struct of arrays (architecture.md, "state as structs of arrays"): one
// contiguous array per field, indexed by particle. Per-particle material index into a table of
// Material (E, nu, rho). Mass and moment of inertia are those of a solid sphere,
// m = 4/3 pi r^3 rho, I = 2/5 m r^2. SI units throughout (m, kg, s, rad).
#pragma once
#include <cstddef>
#include <numbers>
#include <vector>

#include "dem/vec3.hpp"

namespace kolsky::dem {

/// Elastic grain material. youngs_modulus (Pa), poisson_ratio (-), density (kg/m^3).
struct Material {
  double youngs_modulus = 78e9;
  double poisson_ratio = 0.3;
  double density = 2650;

  double shear_modulus() const { return youngs_modulus / (2 * (1 + poisson_ratio)); }
};

/// Throws kolsky::InputError("", "dem.materials[i]...", rule) on a non-physical material.
void validate(const std::vector<Material>& materials);

/// Mass of a solid sphere of radius r (m) and density rho (kg/m^3), kg.
inline double sphere_mass(double r, double rho) {
  return 4.0 / 3.0 * std::numbers::pi * r * r * r * rho;
}

/// The particle state. Forces and torques are those of the last force evaluation.
struct Particles {
  std::vector<Vec3> x;       ///< centre position, m
  std::vector<Vec3> v;       ///< velocity, m/s
  std::vector<Vec3> omega;   ///< angular velocity, rad/s
  std::vector<Vec3> f;       ///< resultant force, N
  std::vector<Vec3> torque;  ///< resultant torque about the centre, N m
  std::vector<double> radius, mass, inertia;  ///< m, kg, kg m^2
  std::vector<int> material;                  ///< index into the material table

  std::size_t size() const { return x.size(); }
  /// Appends a sphere of radius r (m) made of `materials[mat]`; mass and inertia of a solid
  /// sphere. Precondition: r > 0, 0 <= mat < materials.size().
  void add(const Vec3& position, double r, int mat, const std::vector<Material>& materials,
           const Vec3& velocity = {}, const Vec3& angular_velocity = {});
  void reserve(std::size_t n);
  /// Reorders every field by `order` (new index k takes old particle order[k]).
  void permute(const std::vector<int>& order);
  /// Translational plus rotational kinetic energy (J), summed in index order.
  double kinetic_energy() const;
  bool finite() const;
};

/// Throws kolsky::InputError when a field size, radius, mass or material index is invalid.
void validate(const Particles& p, std::size_t n_materials);

}  // namespace kolsky::dem
