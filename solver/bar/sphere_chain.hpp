// Sphere-chain bar (Sec. 4.3, Eqs. 4.3-4.10): N balls of radius R = d/2 in a line, ball density
// 1.5 rho_bar (Eq. 4.8; Tables 4.1/5.2 print 1.251e3 and 1.251e4, misprints of 12,150: see
// docs/bars.md), linear contacts of stiffness k_n^ball/2 (Eq. 4.6) with k_n^ball = pi R rho c^2
// (Eq. 4.9). Contacts are bonded (carry tension), as a continuous bar does: a tensile reflected
// wave would otherwise open the chain. Ball 0 is at the far end (loaded by the applied stress
// times pi R^2, or free), ball N-1 at the specimen face; it also carries the specimen face mass.
// Leapfrog (central differences); stable for dt < sqrt(m/k) = 2 / omega_max.
#pragma once
#include <optional>
#include <vector>

#include "bar/material.hpp"
#include "bar/pulse.hpp"

namespace kolsky::bar {

class SphereChainBar {
 public:
  SphereChainBar(const BarMaterial& m, const BarGeometry& g, int n_balls,
                 std::optional<Pulse> far_end_load, double face_mass);

  /// Advances all balls from t^n to t^{n+1} under the specimen force F^n on the face ball.
  void step(double t, double dt, double specimen_force);

  double intrusion() const { return d_.back(); }
  double rate() const { return v_.back(); }
  double rate_at_step() const { return face_rate_step_; }
  /// Characteristic split at the face from the last contact stress and the face-ball velocity:
  /// s_in = (sigma + Z w)/2, s_out = (sigma - Z w)/2 (exact for a continuous bar; here it
  /// carries the chain's discreteness error).
  double incoming_at_step() const;
  double outgoing_at_step() const;
  /// Contact stress (compression positive) at `distance` from the face, interpolated between
  /// contacts, at the current step time (the `t` argument must be the time of the last step).
  double gauge_stress(double distance, double t) const;
  /// Eq. 4.10: stress of a single travelling wave from a ball's velocity, sigma = rho c v.
  double velocity_stress(int ball) const;
  double face_kinetic_energy() const;
  /// Kinetic energy of the balls (face ball without the specimen's face mass) plus spring
  /// energy, in the leapfrog's own measure: m v^{n-1/2} v^{n+1/2} / 2 + k x^n^2 / 2, the
  /// quantity the scheme conserves exactly for linear springs. The kinetic energy of the
  /// mid-step velocity, m ((v^- + v^+)/2)^2 / 2, exceeds it by m (a dt)^2 / 8, a share
  /// (omega dt)^2 / 8 of the energy in the chain: 0.6 % at 30 kHz and the default dt, which
  /// read as energy growth (delivered energy -0.02 J before the wave reached the specimen).
  double internal_energy() const;
  /// Energy delivered to the face so far: work of the applied load minus what the chain holds.
  double delivered_energy() const { return applied_work_ - internal_energy(); }
  double stable_dt() const;
  bool finite() const;
  int size() const { return static_cast<int>(d_.size()); }
  const SphereChainProperties& properties() const { return props_; }
  const std::vector<double>& velocities() const { return v_; }
  const BarMaterial& material() const { return m_; }
  const BarGeometry& geometry() const { return g_; }

  /// Checkpoint/restart: the balls' state and the work/power bookkeeping.
  struct State {
    std::vector<double> d, v, v_prev, f_contact;
    double face_rate_step = 0, applied_work = 0, power_prev = 0;
    bool first_step = true;
  };
  State save_state() const;
  /// Throws kolsky::InputError ("bars.state") when the ball count differs.
  void restore_state(const State& s);

 private:
  BarMaterial m_;
  BarGeometry g_;
  SphereChainProperties props_;
  std::optional<Pulse> load_;
  double face_mass_, area_;
  std::vector<double> d_, v_, v_prev_, f_contact_;  // displacement toward the specimen (+)
  double face_rate_step_ = 0, applied_work_ = 0, power_prev_ = 0;
  bool first_step_ = true;
};

}  // namespace kolsky::bar
