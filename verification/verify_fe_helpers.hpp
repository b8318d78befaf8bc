// Shared drivers for the FE verification files: a smooth face-intrusion ramp (C1 smoothstep,
// so the start excites little ringing) applied to an FeSpecimen, and number formatting for
// RecordProperty (the measured values land in the GoogleTest XML report).
#pragma once
#include <cstdio>
#include <functional>
#include <string>

#include "fe/fe_specimen.hpp"

namespace kolsky::fe::verify {

/// Pseudo-tensor sand (Sec. 2.3.2 defaults) with a stiffening compaction EOS of the magnitude of
/// Sec. 2.3.4 (initial bulk slope 145 MPa); K_u = 2 GPa exceeds every loading slope.
inline PseudoTensorModeI sand_like() {
  PseudoTensorModeI sand;
  sand.eos.loading.x = {0.0, 0.05, 0.10, 0.20};
  sand.eos.loading.y = {0.0, 7.25e6, 18e6, 60e6};
  sand.eos.unloading_bulk_modulus = 2e9;
  return sand;
}

/// 0 -> 1 over [0, 1] with zero slope at both ends.
inline double smoothstep(double s) {
  if (s <= 0.0) return 0.0;
  if (s >= 1.0) return 1.0;
  return s * s * (3.0 - 2.0 * s);
}

/// Pushes the front face in to `strain` * L over `ramp` seconds (back face held), holds for
/// `hold` seconds, at dt = fraction * stable dt of the undeformed specimen. `each` sees every
/// step's face forces.
inline void ramp_and_hold(FeSpecimen& s, double strain, double ramp, double hold, double fraction,
                          const std::function<void(const FaceForces&)>& each = {}) {
  const double dt = fraction * s.stable_dt();
  const long n = static_cast<long>((ramp + hold) / dt);
  FaceState f;
  for (long k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * dt;
    const double x = strain * s.length() * smoothstep(t / ramp);
    f.rate_front = (x - f.intrusion_front) / dt;
    f.intrusion_front = x;
    const FaceForces ff = s.forces(f);
    if (each) each(ff);
    s.advance(dt);
  }
}

/// Axial strain of the specimen from its own axis nodes (compression +): unlike mean_strain(),
/// free of the face penetrations.
inline double axial_strain(const FeSpecimen& s) {
  const Nodes& nd = s.body().nodes();
  const Block& b = s.specimen_block();
  const auto bottom = static_cast<std::size_t>(b.node(0, 0));
  const auto top = static_cast<std::size_t>(b.node(0, b.n_z));
  return (nd.uz[bottom] - nd.uz[top]) / s.length();
}

inline std::string sci(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4e", x);
  return b;
}

}  // namespace kolsky::fe::verify
