// Breakage counts, lost volume and the fines curve (breakage_ledger.hpp).
#include "dem/breakage_ledger.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "dem/apollonian.hpp"
#include "psd/hardin_breakage.hpp"

namespace kolsky::dem {

namespace {

auto key(const psd::FractalFines& f) { return std::tie(f.d_max, f.d_min, f.alpha); }

}  // namespace

double record_break(BreakageLedger& ledger, const BreakageParams& p, double parent_radius,
                    unsigned parent_generation) {
  if (!(std::isfinite(parent_radius) && parent_radius > 0))
    throw std::invalid_argument("record_break: parent radius must be finite and > 0 m");
  const psd::FractalFines add{
      lost_volume_fraction() * (4.0 / 3.0) * std::numbers::pi * parent_radius * parent_radius *
          parent_radius,
      p.fines_d_min, 2.0 * smallest_daughter_ratio() * parent_radius, p.fines_fractal_dimension};
  if (!(add.d_max > add.d_min))
    throw std::invalid_argument(
        "record_break: the smallest daughter's diameter (Eq. 5.16 d_max) is not above fines_d_min");

  auto& f = ledger.fines;
  const auto it = std::lower_bound(f.begin(), f.end(), add,
                                   [](const auto& a, const auto& b) { return key(a) < key(b); });
  if (it != f.end() && key(*it) == key(add))
    it->volume += add.volume;
  else
    f.insert(it, add);

  ledger.lost_volume += add.volume;
  if (parent_generation == 0)
    ++ledger.n_primary;
  else
    ++ledger.n_secondary;
  return add.volume;
}

psd::GrainSizeCurve current_curve(const BreakageLedger& ledger,
                                  std::span<const double> diameters_of_simulated_grains,
                                  std::span<const double> sizes) {
  if (sizes.empty()) throw std::invalid_argument("current_curve: no sizes");
  for (std::size_t k = 0; k < sizes.size(); ++k)
    if (!(std::isfinite(sizes[k]) && sizes[k] > 0 && (k == 0 || sizes[k] > sizes[k - 1])))
      throw std::invalid_argument("current_curve: sizes must be finite, > 0, strictly increasing");

  double top = 0;  // the largest size holding mass: every curve must pass 100 % there
  for (double d : diameters_of_simulated_grains) top = std::max(top, d);
  for (const auto& fi : ledger.fines) top = std::max(top, fi.d_max);

  psd::GrainSizeCurve c;
  c.diameter.assign(sizes.begin(), sizes.end());
  if (sizes.back() < top) c.diameter.push_back(top);
  c.percent_passing = psd::passing_with_fines(diameters_of_simulated_grains, ledger.fines,
                                              c.diameter);
  // Sums of the same volumes in another order: 100 up to rounding at and beyond `top`.
  for (double& v : c.percent_passing) v = std::min(v, 100.0);
  c.percent_passing.back() = 100.0;
  return c;
}

double hardin_br(const psd::GrainSizeCurve& initial, const psd::GrainSizeCurve& current,
                 double threshold) {
  return psd::hardin_breakage(initial, current, threshold).relative;
}

}  // namespace kolsky::dem
