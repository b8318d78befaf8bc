// The breakage model's closed forms, the grains' random streams and the two limits
// (breakage_model.hpp).
#include "dem/breakage_model.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <variant>

#include "core/errors.hpp"
#include "core/hash.hpp"
#include "core/rng.hpp"
#include "dem/apollonian.hpp"

namespace kolsky::dem {

namespace {

bool positive(double v) { return std::isfinite(v) && v > 0; }

// SplitMix64's Weyl increment: SplitMix64(key + n * kGamma).next() is output n + 1 of the
// stream SplitMix64(key), so a grain's draw is one step of a counter-based generator.
constexpr std::uint64_t kGamma = 0x9e3779b97f4a7c15ULL;

// 64 random bits for (seed, purpose, counter). The key of a (seed, purpose) stream is one
// SplitMix64 step of seed ^ FNV-1a(purpose), so purposes get unrelated streams; within one,
// distinct counters give distinct outputs (the mixer is a bijection). Two purposes' streams
// are the same Weyl sequence at offsets that differ by a pseudo-random j (key_B - key_A =
// j kGamma mod 2^64): they overlap within any 1e12 ids with probability ~2^-23, and even then only
// pair grain id with grain id + j, never a grain with itself.
std::uint64_t stream_bits(std::uint64_t seed, std::string_view purpose, std::uint64_t counter) {
  const std::uint64_t key = SplitMix64(seed ^ fnv1a_64(purpose)).next();
  return SplitMix64(key + counter * kGamma).next();
}

// Top 53 bits: uniform on {0, 2^-53, ..., 1 - 2^-53}, i.e. [0, 1) as Eq. 5.15's U(0,1).
double to_unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

}  // namespace

void validate(const BreakageParams& p, const std::string& path) {
  const auto fail = [&](const char* key, const std::string& rule) {
    throw InputError("", path + "." + key, rule);
  };
  std::visit([&](const auto& c) { validate(c, path); }, p.criterion);
  if (p.coordination_limit < 0) fail("coordination_limit", "must be >= 0 (0 switches it off)");
  if (!(p.comminution_factor > 0 && p.comminution_factor < 1))
    fail("comminution_factor", "must be in (0, 1)");
  if (!positive(p.fines_fractal_dimension)) fail("fines_fractal_dimension", "must be finite and > 0");
  if (!positive(p.fines_d_min)) fail("fines_d_min", "must be finite and > 0 m");
  if (!positive(p.hardin_threshold)) fail("hardin_threshold", "must be finite and > 0 m");
  if (p.cadence.check_interval < 1) fail("check_interval", "must be >= 1");
  if (!(p.cadence.check_period >= 0) || !std::isfinite(p.cadence.check_period))
    fail("check_period", "must be >= 0 (s)");
}

void validate_against_d50(const BreakageParams& p, double d50_initial, const std::string& path) {
  if (!positive(d50_initial))
    throw std::invalid_argument("validate_against_d50: d50 must be finite and > 0 m");
  const double d_max = smallest_daughter_diameter(p, d50_initial);
  if (!(p.fines_d_min < d_max))
    throw InputError("", path + ".fines_d_min",
                     "must be below the fines' d_max of the smallest grain that may break, "
                     "0.448 R = 0.224 x comminution_factor x d50 = " + std::to_string(d_max) +
                         " m");
}

double upscaled_sigma_lim0(double sigma_lim0_original, double upscaling_factor, double m1) {
  // (1/N)^(-3/m1) written as N^(3/m1) (targets.md 5e.8: the sign is consistent).
  return sigma_lim0_original * std::pow(upscaling_factor, 3.0 / m1);
}

double sigma_lim0_between(double sigma_ref, double n_ref, double n, double m1) {
  const double e = 3.0 / m1;
  return sigma_ref * std::pow(n, e) / std::pow(n_ref, e);
}

double critical_force(double sigma_lim, double r_eff, double e_eff) {
  // F = s pi a^2 with a^3 = q F, q = 3 r'/(4 E')  =>  F = s pi (q F)^(2/3)  =>  F^(1/3) = s pi
  // q^(2/3)  =>  F = (s pi)^3 q^2. Products only: a few ulp, no pow.
  const double s = sigma_lim * std::numbers::pi;
  const double q = 0.75 * r_eff / e_eff;
  return s * s * s * q * q;
}

double critical_overlap(double sigma_lim, double r_eff, double e_eff) {
  const double g = 0.75 * std::numbers::pi * sigma_lim / e_eff;  // 3 pi sigma / (4 E')
  return r_eff * g * g;
}

double mean_hertz_pressure(double force, double r_eff, double e_eff) {
  const double a = std::cbrt(0.75 * force * r_eff / e_eff);  // Hertz contact radius (m)
  return force / (std::numbers::pi * a * a);
}

double strength_uniform(std::uint64_t seed, std::uint64_t grain_id) {
  return to_unit(stream_bits(seed, "kolsky.breakage.var", grain_id));
}

double replacement_spin_angle(std::uint64_t seed, std::uint64_t grain_id) {
  constexpr double two_pi = 2 * std::numbers::pi;
  const double phi = two_pi * to_unit(stream_bits(seed, "kolsky.breakage.spin", grain_id));
  // 2 pi (1 - 2^-53) can round up to 2 pi; keep the half-open interval.
  return phi < two_pi ? phi : std::nextafter(two_pi, 0.0);
}

std::uint64_t daughter_id(std::uint64_t parent_id, unsigned k) {
  if (k >= kApollonianCount) throw std::out_of_range("daughter_id: k must be in 0..13");
  // K_k: outputs 1..14 of one fixed SplitMix64 stream, distinct since its mixer is bijective.
  SplitMix64 keys(fnv1a_64("kolsky.breakage.daughter"));
  std::uint64_t key = keys.next();
  for (unsigned i = 0; i < k; ++i) key = keys.next();
  return SplitMix64(parent_id ^ key).next();
}

int counted_coordination(const BreakageParams& p, int n_grain_contacts, int n_wall_contacts) {
  return n_grain_contacts + (p.count_wall_contacts ? n_wall_contacts : 0);
}

bool coordination_allows_break(const BreakageParams& p, int coordination) {
  // "lower than c_lim" (5e.9): strictly; c_lim = 0 is the text's "no contact-limit criterion".
  return p.coordination_limit == 0 || coordination < p.coordination_limit;
}

double comminution_diameter(const BreakageParams& p, double d50_initial) {
  return p.comminution_factor * d50_initial;
}

bool above_comminution_limit(const BreakageParams& p, double diameter, double d50_initial) {
  return !(diameter < comminution_diameter(p, d50_initial));
}

bool may_break(const BreakageParams& p, double diameter, double d50_initial, int coordination) {
  return coordination_allows_break(p, coordination) &&
         above_comminution_limit(p, diameter, d50_initial);
}

bool grain_breaks(const BreakageParams& p, double diameter, double d50_initial, int coordination,
                  double load_ratio) {
  return load_ratio >= 1.0 && may_break(p, diameter, d50_initial, coordination);
}

double smallest_daughter_diameter(const BreakageParams& p, double d50_initial) {
  return smallest_daughter_ratio() * comminution_diameter(p, d50_initial);
}

}  // namespace kolsky::dem
