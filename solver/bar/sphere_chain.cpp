#include "bar/sphere_chain.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace kolsky::bar {

SphereChainBar::SphereChainBar(const BarMaterial& m, const BarGeometry& g, int n_balls,
                               std::optional<Pulse> far_end_load, double face_mass)
    : m_(m), g_(g), props_(sphere_chain_properties(m, g.diameter)),
      load_(std::move(far_end_load)), face_mass_(face_mass) {
  area_ = std::numbers::pi * props_.radius * props_.radius;  // = bar area: ball stands for 2R of bar
  const size_t n = static_cast<size_t>(n_balls);
  d_.assign(n, 0.0);
  v_.assign(n, 0.0);
  v_prev_.assign(n, 0.0);
  f_contact_.assign(n - 1, 0.0);
}

void SphereChainBar::step(double t, double dt, double specimen_force) {
  const size_t n = d_.size();
  const double k = props_.contact_stiffness;
  for (size_t i = 0; i + 1 < n; ++i) f_contact_[i] = k * (d_[i] - d_[i + 1]);
  v_prev_ = v_;
  const double m = props_.ball_mass;
  const double applied = load_ ? evaluate(*load_, t) * area_ : 0.0;
  for (size_t i = 0; i < n; ++i) {
    double f = (i == 0 ? applied : f_contact_[i - 1]) - (i + 1 < n ? f_contact_[i] : 0.0);
    double mass = m;
    if (i + 1 == n) {
      f -= specimen_force;
      mass += face_mass_;
    }
    v_[i] += dt * f / mass;
    d_[i] += dt * v_[i];
  }
  face_rate_step_ = 0.5 * (v_prev_.back() + v_.back());
  const double power = applied * 0.5 * (v_prev_.front() + v_.front());
  if (!first_step_) applied_work_ += 0.5 * dt * (power_prev_ + power);
  power_prev_ = power;
  first_step_ = false;
}

SphereChainBar::State SphereChainBar::save_state() const {
  return {d_, v_, v_prev_, f_contact_, face_rate_step_, applied_work_, power_prev_, first_step_};
}

void SphereChainBar::restore_state(const State& s) {
  const size_t n = d_.size();
  if (s.d.size() != n || s.v.size() != n || s.v_prev.size() != n || s.f_contact.size() + 1 != n)
    throw InputError("", "bars.state", "the state has another ball count than the chain (" +
                                           std::to_string(n) + " balls)");
  d_ = s.d;
  v_ = s.v;
  v_prev_ = s.v_prev;
  f_contact_ = s.f_contact;
  face_rate_step_ = s.face_rate_step;
  applied_work_ = s.applied_work;
  power_prev_ = s.power_prev;
  first_step_ = s.first_step;
}

double SphereChainBar::incoming_at_step() const {
  const double sigma = f_contact_.back() / area_;
  return 0.5 * (sigma + m_.specific_impedance() * face_rate_step_);
}

double SphereChainBar::outgoing_at_step() const {
  const double sigma = f_contact_.back() / area_;
  return 0.5 * (sigma - m_.specific_impedance() * face_rate_step_);
}

double SphereChainBar::gauge_stress(double distance, double /*t*/) const {
  // Contact i (between balls i and i+1) sits (N-1-i) ball diameters from the face.
  const double n_last = static_cast<double>(d_.size() - 1);
  const double s = n_last - distance / (2.0 * props_.radius);
  const double clamped = std::fmin(std::fmax(s, 0.0), static_cast<double>(f_contact_.size() - 1));
  const size_t i = static_cast<size_t>(std::floor(clamped));
  const size_t j = i + 1 < f_contact_.size() ? i + 1 : i;
  const double w = clamped - static_cast<double>(i);
  return ((1.0 - w) * f_contact_[i] + w * f_contact_[j]) / area_;
}

double SphereChainBar::velocity_stress(int ball) const {
  return m_.specific_impedance() * v_[static_cast<size_t>(ball)];
}

double SphereChainBar::face_kinetic_energy() const {
  return 0.5 * face_mass_ * face_rate_step_ * face_rate_step_;
}

double SphereChainBar::internal_energy() const {
  double e = 0.0;
  const double m = props_.ball_mass;
  for (size_t i = 0; i < v_.size(); ++i) e += 0.5 * m * v_prev_[i] * v_[i];  // see the header
  for (double f : f_contact_) e += 0.5 * f * f / props_.contact_stiffness;
  return e;
}

double SphereChainBar::stable_dt() const {
  return std::sqrt(props_.ball_mass / props_.contact_stiffness);
}

bool SphereChainBar::finite() const {
  return std::isfinite(d_.back()) && std::isfinite(v_.back()) && std::isfinite(d_.front());
}

}  // namespace kolsky::bar
