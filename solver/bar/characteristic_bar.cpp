#include "bar/characteristic_bar.hpp"

#include <cmath>
#include <limits>

#include "core/table.hpp"

namespace kolsky::bar {

CharacteristicBar::CharacteristicBar(const BarMaterial& m, const BarGeometry& g,
                                     std::optional<Pulse> far_end_load, double face_mass)
    : m_(m), g_(g), load_(std::move(far_end_load)), face_mass_(face_mass) {
  area_ = g.area();
  c_ = m.wave_speed();
  z_ = m.specific_impedance();
  transit_ = g.length / c_;
}

double CharacteristicBar::applied(double t) const { return load_ ? evaluate(*load_, t) : 0.0; }

double CharacteristicBar::outgoing(double t) const {
  if (t < 0.0 || s_out_.empty()) return 0.0;
  return interp_uniform(s_out_, 0.0, dt_, t);
}

double CharacteristicBar::incoming(double t) const {
  // The wave emitted at the far end at time t - T: the applied stress minus the arriving
  // outgoing wave (a stress boundary reflects it with inverted sign).
  return applied(t - transit_) - outgoing(t - 2.0 * transit_);
}

void CharacteristicBar::step(double t, double dt, double specimen_force) {
  dt_ = dt;
  s_in_step_ = incoming(t);
  const double drive = 2.0 * area_ * s_in_step_;
  const double damping = area_ * z_;
  const double w_old = rate_half_;
  if (face_mass_ > 0.0) {
    rate_half_ = ((face_mass_ - 0.5 * dt * damping) * w_old + dt * (drive - specimen_force)) /
                 (face_mass_ + 0.5 * dt * damping);
    rate_step_ = 0.5 * (w_old + rate_half_);
  } else {
    // Massless face: the characteristic relation fixes w^n; the position advances with the
    // Adams-Bashforth extrapolation w^{n+1/2} = 1.5 w^n - 0.5 w^{n-1} (second order; stable
    // while dt k_face / (A Z) < 1, far from the penalty/wall stiffnesses met in practice).
    const double w_prev = rate_step_;
    rate_step_ = (drive - specimen_force) / damping;
    rate_half_ = s_out_.empty() ? rate_step_ : 1.5 * rate_step_ - 0.5 * w_prev;
  }
  const double s_out = s_in_step_ - z_ * rate_step_;
  s_out_.push_back(s_out);
  const double power = area_ * (s_in_step_ * s_in_step_ - s_out * s_out) / z_;
  if (s_out_.size() > 1) delivered_ += 0.5 * dt * (power_prev_ + power);
  power_prev_ = power;
  intrusion_ += dt * rate_half_;
}

double CharacteristicBar::gauge_stress(double distance, double t) const {
  const double to_face = distance / c_;
  return incoming(t + to_face) + outgoing(t - to_face);
}

CharacteristicBar::State CharacteristicBar::save_state() const {
  return {intrusion_, rate_half_, rate_step_, s_in_step_, dt_, delivered_, power_prev_, s_out_};
}

void CharacteristicBar::restore_state(const State& s) {
  intrusion_ = s.intrusion;
  rate_half_ = s.rate_half;
  rate_step_ = s.rate_step;
  s_in_step_ = s.s_in_step;
  dt_ = s.dt;
  delivered_ = s.delivered;
  power_prev_ = s.power_prev;
  s_out_ = s.s_out;
}

double CharacteristicBar::stable_dt() const { return std::numeric_limits<double>::infinity(); }

bool CharacteristicBar::finite() const {
  return std::isfinite(intrusion_) && std::isfinite(rate_half_) &&
         (s_out_.empty() || std::isfinite(s_out_.back()));
}

}  // namespace kolsky::bar
