// Characteristic ("delay line") elastic bar: exact 1-D wave propagation (d'Alembert). The bar
// holds the history of the wave it sends away from the specimen face; everything else follows
// from the far-end condition (an applied stress history, or a free end when there is none):
//   far end:   s_emit(t) = sigma_app(t) - s_out(t - T),             T = L / c
//   face:      s_in(t)   = s_emit(t - T),
//              face stress = 2 s_in - Z w,  s_out = s_in - Z w       (Z = rho c, w = intrusion rate)
// Stresses compression positive. The face degree of freedom carries the specimen's face mass m:
//   m dw/dt = A (2 s_in - Z w) - F,   F = force from the specimen (central differences with the
// bar dashpot A Z w taken implicitly, so it adds no stability limit). With m = 0 the face
// follows the characteristic relation w = (2 A s_in - F) / (A Z) directly.
#pragma once
#include <optional>
#include <vector>

#include "bar/material.hpp"
#include "bar/pulse.hpp"

namespace kolsky::bar {

class CharacteristicBar {
 public:
  /// far_end_load: stress applied at the far end (the incident bar's pulse); none = free end.
  CharacteristicBar(const BarMaterial& m, const BarGeometry& g, std::optional<Pulse> far_end_load,
                    double face_mass);

  /// Advances the face from t^n to t^{n+1} under the specimen force F^n (compression positive)
  /// and records the outgoing wave at t^n. Steps must be uniform (dt fixed after the first).
  void step(double t, double dt, double specimen_force);

  double intrusion() const { return intrusion_; }       ///< at t^{n+1}, m
  double rate() const { return rate_half_; }            ///< at t^{n+1/2}, m/s
  double rate_at_step() const { return rate_step_; }    ///< at t^n, m/s
  double incoming_at_step() const { return s_in_step_; }///< s_in(t^n) at the face, Pa
  double outgoing_at_step() const { return s_out_.empty() ? 0.0 : s_out_.back(); }
  /// Stress (compression positive) at `distance` from the face at time t <= t^n.
  double gauge_stress(double distance, double t) const;
  double face_kinetic_energy() const { return 0.5 * face_mass_ * rate_step_ * rate_step_; }
  /// Energy the bar has delivered to its face so far (J): integral of A (s_in^2 - s_out^2)/Z,
  /// i.e. W_i - W_r for the incident bar and -W_t for the transmission bar (Eqs. 2.11-2.13).
  double delivered_energy() const { return delivered_; }
  double stable_dt() const;
  bool finite() const;
  const BarMaterial& material() const { return m_; }
  const BarGeometry& geometry() const { return g_; }

  /// Checkpoint/restart: everything step() carries from one step to the next, including the
  /// whole outgoing-wave history (the far-end reflection and the gauges read it back).
  struct State {
    double intrusion = 0, rate_half = 0, rate_step = 0, s_in_step = 0, dt = 0;
    double delivered = 0, power_prev = 0;
    std::vector<double> s_out;
  };
  State save_state() const;
  void restore_state(const State& s);

 private:
  double incoming(double t) const;
  double outgoing(double t) const;  // s_out history, zero before t = 0
  double applied(double t) const;
  BarMaterial m_;
  BarGeometry g_;
  std::optional<Pulse> load_;
  double face_mass_, area_, z_, c_, transit_;
  double intrusion_ = 0, rate_half_ = 0, rate_step_ = 0, s_in_step_ = 0, dt_ = 0;
  double delivered_ = 0, power_prev_ = 0;
  std::vector<double> s_out_;  // s_out at t^n = n dt
};

}  // namespace kolsky::bar
