#include "bar/specimen_column.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace kolsky::bar {

namespace {
// Largest tangent modulus of a material law: sets the Courant limit.
double max_tangent(const ColumnMaterial& m) {
  struct {
    double operator()(const LinearElastic& e) const { return e.constrained_modulus; }
    double operator()(const TabulatedCompaction& c) const {
      double k = c.unloading_modulus;
      for (size_t i = 0; i + 1 < c.loading.x.size(); ++i)
        k = std::max(k, (c.loading.y[i + 1] - c.loading.y[i]) / (c.loading.x[i + 1] - c.loading.x[i]));
      return k;
    }
  } v;
  return std::visit(v, m);
}
}  // namespace

SpecimenColumn::SpecimenColumn(const ColumnParams& p) : p_(p) {
  area_ = std::numbers::pi * p.diameter * p.diameter / 4.0;
  h_ = p.length / p.n_elements;
  element_mass_ = p.density * area_ * h_;
  const size_t n_nodes = static_cast<size_t>(p.n_elements) + 1;
  u_.assign(n_nodes, 0.0);
  v_.assign(n_nodes, 0.0);
  const size_t n = static_cast<size_t>(p.n_elements);
  strain_.assign(n, 0.0);
  stress_.assign(n, 0.0);
  max_strain_.assign(n, 0.0);
  work_.assign(n, 0.0);
}

double SpecimenColumn::stable_dt() const {
  return h_ / std::sqrt(max_tangent(p_.material) / p_.density);
}

double SpecimenColumn::stress_of(size_t e, double strain) const {
  if (const auto* el = std::get_if<LinearElastic>(&p_.material)) return el->constrained_modulus * strain;
  const auto& c = std::get<TabulatedCompaction>(p_.material);
  const double emax = std::max(max_strain_[e], strain);
  const double on_curve = c.loading(emax);
  // Unloading/reloading line from the largest strain reached; sand carries no tension.
  return std::max(0.0, on_curve - c.unloading_modulus * (emax - strain));
}

FaceForces SpecimenColumn::forces(const FaceState& faces) {
  const size_t m = u_.size() - 1;
  u_[0] = faces.intrusion_front;
  u_[m] = -faces.intrusion_back;
  const double element_volume = area_ * h_;
  for (size_t e = 0; e < strain_.size(); ++e) {
    const double eps = (u_[e] - u_[e + 1]) / h_;  // compression positive
    const double sig = stress_of(e, eps);
    // Trapezoid rule of sigma d(eps): exact for piecewise-linear paths between steps.
    work_[e] += 0.5 * (sig + stress_[e]) * (eps - strain_[e]) * element_volume;
    strain_[e] = eps;
    stress_[e] = sig;
    max_strain_[e] = std::max(max_strain_[e], eps);
  }
  return FaceForces{area_ * stress_.front(), area_ * stress_.back()};
}

void SpecimenColumn::advance(double dt) {
  const size_t m = u_.size() - 1;
  kinetic_interior_ = 0.0;
  for (size_t i = 1; i < m; ++i) {
    const double f = area_ * (stress_[i - 1] - stress_[i]);
    const double v_old = v_[i];
    v_[i] += dt * f / element_mass_;
    // Kinetic energy at t^n from the mean of the half-step velocities.
    const double v_mid = 0.5 * (v_old + v_[i]);
    kinetic_interior_ += 0.5 * element_mass_ * v_mid * v_mid;
    u_[i] += dt * v_[i];
  }
}

SpecimenEnergy SpecimenColumn::energy() const {
  double w = 0.0;
  for (double x : work_) w += x;
  return SpecimenEnergy{kinetic_interior_, w};
}

double SpecimenColumn::mean_strain() const {
  return (u_.front() - u_.back()) / p_.length;
}

bool SpecimenColumn::finite() const {
  for (size_t i = 0; i < u_.size(); ++i)
    if (!std::isfinite(u_[i]) || !std::isfinite(v_[i])) return false;
  for (double s : stress_)
    if (!std::isfinite(s)) return false;
  return true;
}

}  // namespace kolsky::bar

namespace kolsky::bar {

SpecimenColumn::State SpecimenColumn::save_state() const {
  return {u_, v_, strain_, stress_, max_strain_, work_, kinetic_interior_};
}

void SpecimenColumn::restore_state(const State& s) {
  const size_t nodes = u_.size(), elements = strain_.size();
  if (s.u.size() != nodes || s.v.size() != nodes || s.strain.size() != elements ||
      s.stress.size() != elements || s.max_strain.size() != elements ||
      s.work.size() != elements)
    throw InputError("", "specimen.state", "the state has another element count than the column (" +
                                               std::to_string(elements) + " elements)");
  u_ = s.u;
  v_ = s.v;
  strain_ = s.strain;
  stress_ = s.stress;
  max_strain_ = s.max_strain;
  work_ = s.work;
  kinetic_interior_ = s.kinetic_interior;
}

}  // namespace kolsky::bar
