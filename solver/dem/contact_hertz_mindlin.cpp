// Hertz-Mindlin material-pair tables and Hertz closed forms (see the header for sources).
#include "dem/contact_hertz_mindlin.hpp"

#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "dem/contact_damping.hpp"
#include "dem/hertz.hpp"

namespace kolsky::dem {

namespace {
// Compliance terms; an infinite modulus (rigid wall) gives 0.
double shear_compliance(const Material& m) {
  return std::isinf(m.youngs_modulus)
             ? 0.0
             : 2 * (2 - m.poisson_ratio) * (1 + m.poisson_ratio) / m.youngs_modulus;
}
}  // namespace

double effective_modulus(const Material& a, const Material& b) {
  return effective_modulus(a.youngs_modulus, a.poisson_ratio, b.youngs_modulus, b.poisson_ratio);
}

double effective_shear_modulus(const Material& a, const Material& b) {
  return 1.0 / (shear_compliance(a) + shear_compliance(b));
}

HertzMindlinPair make_hertz_mindlin_pair(const Material& a, const Material& b,
                                         const HertzMindlinParams& p) {
  HertzMindlinPair pair;
  pair.normal.e_star = effective_modulus(a, b);
  pair.tangential.g_star = effective_shear_modulus(a, b);
  pair.tangential.friction = p.friction;
  pair.damping.beta = damping_ratio_from_restitution(p.restitution);
  pair.tangential_damping_scale = std::sqrt(4 * pair.tangential.g_star / pair.normal.e_star);
  return pair;
}

void validate(const HertzMindlinParams& p, const std::string& path) {
  if (!(p.friction >= 0 && std::isfinite(p.friction)))
    throw InputError("", path + ".friction", "must be finite and >= 0");
  if (!(p.restitution > 0 && p.restitution <= 1))
    throw InputError("", path + ".restitution", "must be in (0, 1]");
}

HertzMindlin::HertzMindlin(const std::vector<Material>& materials, const HertzMindlinParams& p)
    : params_(p), n_(static_cast<int>(materials.size())) {
  dem::validate(materials);  // qualified: the member validate(path) hides the free functions
  dem::validate(p, "dem.contact_law");
  table_.reserve(materials.size() * materials.size());
  for (const auto& a : materials)
    for (const auto& b : materials) table_.push_back(make_hertz_mindlin_pair(a, b, p));
}

HertzMindlinWall::HertzMindlinWall(const std::vector<Material>& materials, const Material& wall,
                                   const HertzMindlinParams& p)
    : params_(p) {
  dem::validate(materials);
  dem::validate(p, "dem.walls.law");
  if (!(wall.youngs_modulus > 0) || !(wall.poisson_ratio > -1 && wall.poisson_ratio < 0.5))
    throw InputError("", "dem.walls.material", "E must be > 0 (+inf: rigid), nu in (-1, 0.5)");
  for (const auto& a : materials) table_.push_back(make_hertz_mindlin_pair(a, wall, p));
}

double HertzImpact::max_overlap() const {
  return std::pow(15.0 * m_eff * speed * speed / (16.0 * e_star * std::sqrt(r_eff)), 0.4);
}

double HertzImpact::peak_force() const {
  return hertz_normal_force(e_star, r_eff, max_overlap());
}

double HertzImpact::contact_time() const {
  const double integral = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  return 2.0 * integral * max_overlap() / speed;
}

double rayleigh_time_step(double radius, const Material& m) {
  return std::numbers::pi * radius * std::sqrt(m.density / m.shear_modulus()) /
         (0.1631 * m.poisson_ratio + 0.8766);
}

}  // namespace kolsky::dem
