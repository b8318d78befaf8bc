// The FE specimen driven through the specimen-coupling interface exactly as shpb/simulation.cpp
// drives a specimen, between two elastic bars reduced to their faces (face_mass() = 0: each face
// follows the characteristic relation w = (2 A s_in - F)/(A Z), Z = rho c; see
// bar/characteristic_bar.hpp). The incident bar brings a 40 MPa pulse ramped over 100 us; the
// transmission bar brings nothing. Checks: once the pulse has risen, the energy the bars
// deliver, integral of A (s_in^2 - s_out^2)/Z dt (Eqs. 2.11-2.13), equals what the specimen
// holds; a frictionless specimen reaches stress equilibrium, alpha = |F_front - F_back| / mean
// < 0.05 (Eq. 2.15), after ringing up.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fe/fe_specimen.hpp"
#include "verify_fe_helpers.hpp"

namespace kolsky::fe {
namespace {

// A bar face with no mass: the incoming stress s_in(t) is given, the outgoing one follows.
struct BarFace {
  double area, impedance;  // A (m^2), Z = rho c (Pa s/m)
  double intrusion = 0, rate = 0, delivered = 0, power_prev = 0;
  bool started = false;
  void step(double dt, double s_in, double force) {
    rate = (2.0 * area * s_in - force) / (area * impedance);
    const double s_out = s_in - impedance * rate;
    const double power = area * (s_in * s_in - s_out * s_out) / impedance;
    if (started) delivered += 0.5 * dt * (power_prev + power);
    power_prev = power;
    started = true;
    intrusion += dt * rate;
  }
};

TEST(VerifyFeCoupling, BarsDeliverWhatTheSpecimenHoldsAndFacesEquilibrate) {
  FeSpecimenParams p;
  p.n_r = 10;
  p.n_z = 10;
  PseudoTensorModeI sand;
  sand.eos.loading.x = {0.0, 0.05, 0.10, 0.20};
  sand.eos.loading.y = {0.0, 7.25e6, 18e6, 60e6};
  sand.eos.unloading_bulk_modulus = 2e9;
  p.material = sand;
  p.tube = RigidTube{};
  FeSpecimen s(p);
  const double area = std::numbers::pi * 0.0191 * 0.0191 / 4.0;  // 19.1 mm bars (Sec. 2.2)
  const double z = 8100.0 * std::sqrt(200e9 / 8100.0);           // steel (Sec. 2.3.1)
  BarFace front{area, z}, back{area, z};
  const double dt = 0.9 * s.stable_dt();
  const double rise = 100e-6, end = 300e-6;  // a ramped pulse, as shaped SHPB pulses are
  double worst_balance = 0.0, worst_alpha_late = 0.0;
  for (long k = 0; k * dt < end; ++k) {
    const double t = k * dt;
    const double s_in = 40e6 * verify::smoothstep(t / rise);
    // The loop order of shpb/simulation.cpp: faces at t^n -> forces -> specimen -> bars.
    const FaceState faces{front.intrusion, back.intrusion, front.rate, back.rate};
    const FaceForces f = s.forces(faces);
    s.advance(dt);
    front.step(dt, s_in, f.front);
    back.step(dt, 0.0, f.back);
    const double delivered = front.delivered + back.delivered;
    if (t >= rise)
      worst_balance = std::max(worst_balance, std::fabs(s.energy().total() - delivered) / delivered);
    if (t > 150e-6)
      worst_alpha_late = std::max(worst_alpha_late, std::fabs(f.front - f.back) / (0.5 * (f.front + f.back)));
  }
  RecordProperty("worst_energy_balance", verify::sci(worst_balance));
  RecordProperty("worst_alpha_after_150us", verify::sci(worst_alpha_late));
  RecordProperty("final_strain", verify::sci(s.mean_strain()));
  // The bar sums F^n w^n dt, the specimen F dx over the face increments dt w^{n-1} (the face
  // moves by forward Euler): a first-order offset of dt/2 * integral F dw, 1 per cent while the
  // pulse rises, fading as the work grows; the bound is 0.5 per cent.
  EXPECT_LT(worst_balance, 5e-3);
  // Frictionless: equilibrium after ~6 transits of the 24 us loading wave (Sec. 2.4.2).
  EXPECT_LT(worst_alpha_late, 0.05);
  EXPECT_GT(s.mean_strain(), 0.01);  // the pulse did compress the specimen
}

}  // namespace
}  // namespace kolsky::fe
