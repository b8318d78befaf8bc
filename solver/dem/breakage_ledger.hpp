// Book-keeping of breakage events (Sec. 5.2.3): primary and secondary break counts, the volume
// that leaves the simulation at each replacement (1 - 0.5338 of the parent's, Table 5.3), and
// that volume as fines on the grain-size curve by Eq. 5.16 (d_max = diameter of the smallest
// daughter = 2 x 0.2240 x R_parent, d_min and alpha from BreakageParams). The specimen's curve
// (simulated grains plus fines) and Hardin's B_r (75 um threshold, Sec. 5.3.1) are computed
// from it at any time. A plain struct and free functions; the engine owns one per specimen and
// records breaks in its deterministic (parent index) order. Units: m, m^3.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "dem/breakage_model.hpp"
#include "psd/fractal_fines.hpp"
#include "psd/grain_size_curve.hpp"

namespace kolsky::dem {

struct BreakageLedger {
  std::uint64_t n_primary = 0;    ///< breaks of grains of the initial specimen (generation 0)
  std::uint64_t n_secondary = 0;  ///< breaks of daughters (generation >= 1)
  double lost_volume = 0;         ///< m^3, total volume removed from the particles
  /// The lost volume as Eq. 5.16 fines, one entry per distinct (d_max, d_min, alpha), sorted by
  /// that key: breaks of equal-sized parents (a monodisperse specimen, or the daughters of one
  /// size class) add to one entry, so the list grows with distinct parent sizes, not events,
  /// and its content does not depend on the order breaks are recorded in.
  std::vector<psd::FractalFines> fines;
};

/// Records the break of a parent of radius parent_radius (m) and generation parent_generation
/// (0: a grain of the initial specimen -> primary; >= 1: a daughter -> secondary). Adds
/// lost_volume_fraction() x (4/3) pi R^3 to lost_volume and to the fines entry of d_max =
/// 2 smallest_daughter_ratio() R; returns that volume (m^3). Throws std::invalid_argument for a
/// radius that is not finite and > 0, or when d_max <= p.fines_d_min (Eq. 5.16 would be empty;
/// validate_against_d50 rules this out for grains above the comminution limit).
double record_break(BreakageLedger& ledger, const BreakageParams& p, double parent_radius,
                    unsigned parent_generation);

/// Breaks recorded (primary + secondary).
inline std::uint64_t n_breaks(const BreakageLedger& l) { return l.n_primary + l.n_secondary; }
/// Daughters created by primary breaks, as Sec. 5.3.2 counts them (14 per break); the same for
/// secondary with l.n_secondary.
inline std::uint64_t primary_daughters(const BreakageLedger& l) { return 14 * l.n_primary; }
inline std::uint64_t secondary_daughters(const BreakageLedger& l) { return 14 * l.n_secondary; }

/// The specimen's grain-size curve: simulated grains (diameters, m; may be empty if there are
/// fines) plus the ledger's fines, by psd::passing_with_fines at `sizes` (m, finite, > 0,
/// strictly increasing, non-empty). If the sizes stop below the largest grain or d_max, that
/// size is appended so that the curve ends at 100 % (GrainSizeCurve's rule). Between rows the
/// curve is linear in log d and a first row above 0 % is a lump (grain_size_curve.hpp), so put
/// rows where they are wanted (d_min, the 75 um threshold, the sieve sizes). Throws
/// std::invalid_argument on bad sizes or when there is no mass at all.
psd::GrainSizeCurve current_curve(const BreakageLedger& ledger,
                                  std::span<const double> diameters_of_simulated_grains,
                                  std::span<const double> sizes);

/// Hardin's relative breakage B_r of `current` against `initial` over sizes > threshold (m;
/// 75 um in Sec. 5.3.1), by psd::hardin_breakage.
double hardin_br(const psd::GrainSizeCurve& initial, const psd::GrainSizeCurve& current,
                 double threshold = 75e-6);

}  // namespace kolsky::dem
