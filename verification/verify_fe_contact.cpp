// Contact verification of the FE specimen (penalty, Coulomb friction):
//   frictionless faces transmit no shear at all, so an unconfined elastic specimen expands
//   uniformly (u_r = nu eps R, no barrelling);
//   Coulomb faces (mu = 0.3) transmit shear bounded by mu f_n at every node and barrel it;
//   in an SHPB-like dynamic compaction (face at 4.5 m/s, tabulated EOS, rigid tube, mu = 0.2)
//   the penetration stays within the static penalty estimate sigma h / (s M_max), and the
//   energy ledger (kinetic + material + contact + friction = face work) closes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fe/fe_specimen.hpp"
#include "verify_fe_helpers.hpp"

namespace kolsky::fe {
namespace {

constexpr double kPi = std::numbers::pi;

FeSpecimenParams unconfined(double mu) {
  FeSpecimenParams p;
  p.n_r = 6;
  p.n_z = 6;
  p.material = LinearElastic{130e6, 0.3, 1457.5};
  p.tube = NoTube{};
  p.friction_faces = mu;
  p.mass_damping = 1.5e5;  // dynamic relaxation to the static state
  return p;
}

TEST(VerifyFeContact, FrictionlessFacesTransmitNoShear) {
  FeSpecimen s(unconfined(0.0));
  double shear = 0.0;
  verify::ramp_and_hold(s, 1e-3, 400e-6, 600e-6, 0.9,
                        [&](const FaceForces&) { shear = std::max(shear, s.face_shear()); });
  EXPECT_EQ(shear, 0.0);  // mu = 0: the tangential force is identically zero, not just small
  const Nodes& nd = s.body().nodes();
  const Block& b = s.specimen_block();
  const double eps = verify::axial_strain(s);
  const double u_face = nd.ur[static_cast<std::size_t>(b.node(b.n_r, 0))];
  const double u_mid = nd.ur[static_cast<std::size_t>(b.node(b.n_r, b.n_z / 2))];
  RecordProperty("lateral_face_over_mid", verify::sci(u_face / u_mid - 1));
  RecordProperty("lateral_over_nu_eps_R", verify::sci(u_mid / (0.3 * eps * 9.55e-3) - 1));
  // Uniaxial stress is exact for the discrete model; what is left is the relaxation residual.
  EXPECT_NEAR(u_face / u_mid, 1.0, 1e-3);
  EXPECT_NEAR(u_mid / (0.3 * eps * 9.55e-3), 1.0, 5e-3);
}

TEST(VerifyFeContact, CoulombFacesAreCappedAndBarrel) {
  FeSpecimen s(unconfined(0.3));
  double worst_ratio = 0.0;
  verify::ramp_and_hold(s, 1e-3, 400e-6, 600e-6, 0.9, [&](const FaceForces&) {
    for (const ContactSet* c : {&s.front_contact(), &s.back_contact()})
      for (std::size_t k = 0; k < c->node.size(); ++k)
        if (c->normal_force[k] > 0.0)
          worst_ratio = std::max(worst_ratio, std::fabs(c->tangential_force[k]) / c->normal_force[k]);
  });
  RecordProperty("max_shear_over_normal", verify::sci(worst_ratio));
  EXPECT_LE(worst_ratio, 0.3 * (1 + 1e-12));  // the cap is exact up to round-off
  EXPECT_GT(s.face_shear(), 0.0);
  const Nodes& nd = s.body().nodes();
  const Block& b = s.specimen_block();
  const double u_face = nd.ur[static_cast<std::size_t>(b.node(b.n_r, 0))];
  const double u_mid = nd.ur[static_cast<std::size_t>(b.node(b.n_r, b.n_z / 2))];
  RecordProperty("barrel_face_over_mid", verify::sci(u_face / u_mid));
  // Faces held by friction expand less than the mid-height: a barrel.
  EXPECT_LT(u_face, 0.9 * u_mid);
  EXPECT_GE(s.energy_ledger().friction_work, 0.0);  // friction only takes energy
}

TEST(VerifyFeContact, DynamicCompactionPenetrationBoundedAndEnergyCloses) {
  FeSpecimenParams p;
  p.n_r = 10;
  p.n_z = 10;
  p.material = verify::sand_like();
  p.tube = RigidTube{};
  p.friction_faces = p.friction_tube = 0.2;  // Sec. 2.4.2
  FeSpecimen s(p);
  const double dt = 0.9 * s.stable_dt();
  const double v = 480.0 * p.length;  // 480/s (Sec. 2.3.4), reached over 20 us
  const double area = kPi * p.radius * p.radius;
  const double h_z = p.length / p.n_z, m_max = max_constrained_modulus(p.material);
  FaceState f;
  double worst_pen_ratio = 0.0, worst_balance = 0.0;
  for (long k = 0; k * dt < 200e-6; ++k) {
    const double t = k * dt;
    f.rate_front = v * std::min(1.0, t / 20e-6);
    const FaceForces ff = s.forces(f);
    s.advance(dt);
    f.intrusion_front += dt * f.rate_front;
    const double sigma = std::max(ff.front, ff.back) / area;
    // Static estimate of the face penetration: sigma h / (s M_max).
    const double bound = sigma * h_z / (p.penalty_scale * m_max);
    if (sigma > 1e6) worst_pen_ratio = std::max(worst_pen_ratio, s.max_penetration() / bound);
    const FeEnergy e = s.energy_ledger();
    if (k > 100) worst_balance = std::max(worst_balance, std::fabs(e.balance_error()) / e.held());
  }
  RecordProperty("penetration_over_static_estimate", verify::sci(worst_pen_ratio));
  RecordProperty("final_penetration_over_length", verify::sci(s.max_penetration() / p.length));
  RecordProperty("worst_energy_balance", verify::sci(worst_balance));
  // Stress waves make the face load uneven across the nodes; twice the uniform estimate
  // bounds it (measured ~1.2).
  EXPECT_LT(worst_pen_ratio, 2.0);
  EXPECT_LT(s.max_penetration(), 1e-3 * p.length);  // 0.1 per cent of L at 20+ MPa
  // The ledger's terms are each second-order accurate in dt; the bound is 0.5 per cent.
  EXPECT_LT(worst_balance, 5e-3);
  EXPECT_GT(s.energy_ledger().friction_work, 0.0);
}

}  // namespace
}  // namespace kolsky::fe
