// Scatter between packing seeds: the Ch. 4 rotational family (the calibrated k and the
// Sec. 4.4.2 values) repeated on packings that differ only in their random seed, at one
// upscaling factor. It tells which of the Sec. 4.4 comparisons a single packing can resolve:
// a difference between two cases smaller than its seed-to-seed scatter is not a property of
// the model but of the packing drawn.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "chapter4/ch4.hpp"

namespace kolsky::ch4 {

struct SeedCase {
  double seed = 0, k = 1;
  std::size_t grains = 0;
  double porosity = NAN, case_s = 0;
  bool ok = false;
  std::string failure;
  Measures m;                          ///< measure(case, 1 MPa, 3 MPa, limit)
  std::vector<double> strain, stress;  ///< sigma_t(strain) to the first 10 MPa sample, Pa
};

/// Runs every k of `ks` on the set's case `base` with specimen.upscale = n and specimen.seed =
/// each of `seeds` (packings through its cache). Cases come back seed by seed, k by k.
std::vector<SeedCase> seed_study(const harness::Case& base, double n, const std::vector<double>& seeds,
                                 const std::vector<double>& ks, double limit);

/// M 1-10 MPa of the calibrated k relative to k = 1, seed by seed (M(k_cal) / M(1) - 1), with
/// its mean and sample standard deviation (NaN below two seeds) and the mean grain count.
struct FreeScatter {
  std::vector<double> d;
  double mean = NAN, sd = NAN, grains = NAN;
};
FreeScatter calibrated_vs_free(const std::vector<SeedCase>& cases, double k_calibrated);

/// Markdown: one row per case, then mean and standard deviation over the seeds of each
/// measure per k, and for each Sec. 4.4 ordering the number of seeds in which it holds.
std::string seed_table(const std::vector<SeedCase>& cases, const std::vector<double>& ks,
                       double k_calibrated);

}  // namespace kolsky::ch4
