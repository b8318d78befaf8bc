// Particle storage helpers: construction of solid spheres, reordering and validation.
#include "dem/particles.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace kolsky::dem {

void validate(const std::vector<Material>& materials) {
  if (materials.empty()) throw InputError("", "dem.materials", "at least one material is needed");
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const auto& m = materials[i];
    const std::string at = "dem.materials[" + std::to_string(i) + "]";
    if (!(m.youngs_modulus > 0) || !std::isfinite(m.youngs_modulus))
      throw InputError("", at + ".youngs_modulus", "must be finite and > 0");
    if (!(m.poisson_ratio > -1 && m.poisson_ratio < 0.5))
      throw InputError("", at + ".poisson_ratio", "must be in (-1, 0.5)");
    if (!(m.density > 0) || !std::isfinite(m.density))
      throw InputError("", at + ".density", "must be finite and > 0");
  }
}

void Particles::add(const Vec3& position, double r, int mat, const std::vector<Material>& materials,
                    const Vec3& velocity, const Vec3& angular_velocity) {
  const double m = sphere_mass(r, materials.at(mat).density);
  x.push_back(position);
  v.push_back(velocity);
  omega.push_back(angular_velocity);
  f.push_back({});
  torque.push_back({});
  radius.push_back(r);
  mass.push_back(m);
  inertia.push_back(0.4 * m * r * r);
  material.push_back(mat);
}

void Particles::reserve(std::size_t n) {
  x.reserve(n); v.reserve(n); omega.reserve(n); f.reserve(n); torque.reserve(n);
  radius.reserve(n); mass.reserve(n); inertia.reserve(n); material.reserve(n);
}

namespace {
template <class T>
void apply_order(std::vector<T>& a, const std::vector<int>& order) {
  std::vector<T> b(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) b[k] = a[order[k]];
  a.swap(b);
}
}  // namespace

void Particles::permute(const std::vector<int>& order) {
  apply_order(x, order); apply_order(v, order); apply_order(omega, order);
  apply_order(f, order); apply_order(torque, order); apply_order(radius, order);
  apply_order(mass, order); apply_order(inertia, order); apply_order(material, order);
}

double Particles::kinetic_energy() const {
  double e = 0;
  for (std::size_t i = 0; i < size(); ++i)
    e += 0.5 * (mass[i] * norm2(v[i]) + inertia[i] * norm2(omega[i]));
  return e;
}

bool Particles::finite() const {
  for (std::size_t i = 0; i < size(); ++i)
    if (!is_finite(x[i]) || !is_finite(v[i]) || !is_finite(omega[i])) return false;
  return true;
}

void validate(const Particles& p, std::size_t n_materials) {
  const std::size_t n = p.size();
  if (p.v.size() != n || p.omega.size() != n || p.f.size() != n || p.torque.size() != n ||
      p.radius.size() != n || p.mass.size() != n || p.inertia.size() != n || p.material.size() != n)
    throw InputError("", "dem.particles", "all particle fields must have the same length");
  for (std::size_t i = 0; i < n; ++i) {
    const std::string at = "dem.particles[" + std::to_string(i) + "]";
    if (!(p.radius[i] > 0) || !(p.mass[i] > 0) || !(p.inertia[i] > 0))
      throw InputError("", at, "radius, mass and inertia must be > 0");
    if (p.material[i] < 0 || static_cast<std::size_t>(p.material[i]) >= n_materials)
      throw InputError("", at + ".material", "index outside the material table");
    if (!is_finite(p.x[i]) || !is_finite(p.v[i]) || !is_finite(p.omega[i]))
      throw InputError("", at, "position and velocities must be finite");
  }
}

}  // namespace kolsky::dem
