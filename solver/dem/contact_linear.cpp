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

LinearSpring linear_spring(const LinearParams& p) {
  return linear_spring(p.normal_stiffness, p.shear_stiffness, p.friction, p.damping_ratio,
                       p.damping_ratio);
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
  require(s.normal.stiffness > 0 && std::isfinite(s.normal.stiffness),
          path + ".normal_stiffness", "must be finite and > 0");
  require(s.tangential.stiffness >= 0 && std::isfinite(s.tangential.stiffness),
          path + ".shear_stiffness", "must be finite and >= 0");
  require(s.tangential.friction >= 0, path + ".friction", "must be >= 0");
  require(s.damping_normal.ratio >= 0 && s.damping_normal.ratio < 1, path + ".damping_normal",
          "must be in [0, 1)");
  require(s.damping_tangential.ratio >= 0 && s.damping_tangential.ratio < 1,
          path + ".damping_tangential", "must be in [0, 1)");
  require(s.rolling.coefficient >= 0, path + ".rolling_friction", "must be >= 0");
}

void LinearSpring::validate(const std::string& path) const { dem::validate(*this, path); }

void validate(const LinearParams& p, const std::string& path) {
  require(p.normal_stiffness > 0 && std::isfinite(p.normal_stiffness),
          path + ".normal_stiffness", "must be finite and > 0");
  require(p.shear_stiffness >= 0 && std::isfinite(p.shear_stiffness), path + ".shear_stiffness",
          "must be finite and >= 0");
  require(p.friction >= 0 && std::isfinite(p.friction), path + ".friction",
          "must be finite and >= 0");
  require(p.damping_ratio >= 0 && p.damping_ratio < 1, path + ".damping_ratio",
          "must be in [0, 1)");
}

void validate(const LsDynaParams& p, const std::string& path) {
  require(p.normk > 0 && std::isfinite(p.normk), path + ".normk", "must be finite and > 0");
  require(p.sheark >= 0 && std::isfinite(p.sheark), path + ".sheark", "must be finite and >= 0");
  require(p.fric >= 0 && std::isfinite(p.fric), path + ".fric", "must be finite and >= 0");
  require(p.fricr >= 0 && std::isfinite(p.fricr), path + ".fricr", "must be finite and >= 0");
  require(p.ndamp >= 0 && p.ndamp < 1, path + ".ndamp", "must be in [0, 1)");
  require(p.tdamp >= 0 && p.tdamp < 1, path + ".tdamp", "must be in [0, 1)");
}

LsDynaLinear::LsDynaLinear(const std::vector<Material>& materials, const LsDynaParams& p)
    : params_(p), n_(static_cast<int>(materials.size())) {
  dem::validate(materials);  // qualified: the member validate(path) hides the free functions
  dem::validate(p, "dem.contact_law");
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
