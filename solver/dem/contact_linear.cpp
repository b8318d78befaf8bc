// Linear contact laws: construction and stable steps (see contact_linear.hpp).
#include "dem/contact_linear.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace kolsky::dem {

double linear_contact_time_step(double mass, double stiffness, double zeta) {
  if (!(stiffness > 0)) return std::numeric_limits<double>::infinity();
  return std::sqrt(mass / stiffness) * (std::sqrt(1 + zeta * zeta) - zeta);
}

double LinearSpring::stable_dt(double mass) const {
  return std::min(linear_contact_time_step(mass, normal.stiffness, damping_normal.ratio),
                  linear_contact_time_step(mass, 3.5 * tangential.stiffness,
                                           damping_tangential.ratio));
}

LinearSpring linear_spring(double k_n, double k_s, double friction, double damping_normal,
                           double damping_tangential) {
  LinearSpring s;
  s.normal.stiffness = k_n;
  s.tangential.stiffness = k_s;
  s.tangential.friction = friction;
  s.damping_normal.ratio = damping_normal;
  s.damping_tangential.ratio = damping_tangential;
  return s;
}

namespace {
void require(bool ok, const std::string& path, const char* rule) {
  if (!ok) throw InputError("", path, rule);
}
}  // namespace

void validate(const LinearSpring& s, const std::string& path) {
  require(s.normal.stiffness > 0 && std::isfinite(s.normal.stiffness), path + ".k_n",
          "must be finite and > 0");
  require(s.tangential.stiffness >= 0 && std::isfinite(s.tangential.stiffness), path + ".k_s",
          "must be finite and >= 0");
  require(s.tangential.friction >= 0, path + ".friction", "must be >= 0");
  require(s.damping_normal.ratio >= 0 && s.damping_normal.ratio < 1, path + ".damping_normal",
          "must be in [0, 1)");
  require(s.damping_tangential.ratio >= 0 && s.damping_tangential.ratio < 1,
          path + ".damping_tangential", "must be in [0, 1)");
  require(s.rolling.coefficient >= 0, path + ".rolling_friction", "must be >= 0");
}

LsDynaLinear::LsDynaLinear(const std::vector<Material>& materials, const LsDynaParams& p)
    : n_(static_cast<int>(materials.size())) {
  validate(materials);
  require(p.normk > 0, "dem.contact.normk", "must be > 0");
  require(p.sheark >= 0 && p.fric >= 0 && p.fricr >= 0, "dem.contact",
          "sheark, fric and fricr must be >= 0");
  require(p.ndamp >= 0 && p.ndamp < 1 && p.tdamp >= 0 && p.tdamp < 1, "dem.contact",
          "ndamp and tdamp must be in [0, 1)");
  auto k_of = [](const Material& m) { return m.youngs_modulus / (1 - 2 * m.poisson_ratio); };
  for (const auto& a : materials)
    for (const auto& b : materials) table_.push_back(LsDynaPair{k_of(a), k_of(b), p});
}

double LsDynaLinear::stable_dt(double m_min, double r_max) const {
  double dt = std::numeric_limits<double>::infinity();
  for (const auto& pr : table_) {
    const double kn = pr.normal_stiffness(r_max, r_max);  // K_n grows with both radii
    dt = std::min({dt, linear_contact_time_step(m_min, kn, pr.p.ndamp),
                   linear_contact_time_step(m_min, 3.5 * pr.p.sheark * kn, pr.p.tdamp)});
  }
  return dt;
}

}  // namespace kolsky::dem
