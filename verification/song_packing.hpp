// Jammed packings of the reconstructed Song et al. (2009) grain-size curve (the dissertation's
// Ch. 4 sand) in small cylinders, shared by the DEM tests that need a realistic specimen.
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <numbers>
#include <string>

#include "dem/packing.hpp"
#include "io/csv.hpp"
#include "psd/sampling.hpp"

namespace kolsky::testing {

/// The curve upscaled by n, jammed (frictional growth, quenched settling, at most 200
/// settling stages) in a cylinder of the given diameter and length (m), grains E 78 GPa,
/// nu 0.3, rho 2650 kg/m^3, porosity 0.44.
inline dem::PackingParams song_jammed(double n, double diameter, double length,
                                      std::uint64_t seed) {
  const io::CsvTable t = io::read_csv(std::string(KOLSKY_SOURCE_DIR) +
                                      "/data/digitized/chapter4/song2009_psd_reconstructed.csv");
  dem::PackingParams p;
  p.curve = psd::upscale({t.column("diameter_m"), t.column("percent_passing")}, n);
  p.diameter = diameter;
  p.length = length;
  p.seed = seed;
  p.material = dem::Material{78e9, 0.3, 2650};
  p.jam = true;
  p.max_settle_stages = 200;
  return p;
}

/// What every packing procedure guarantees (docs/dem.md, "Packing"): the porosity of the
/// sampled radii within half the largest grain's volume of the target, the count within 5 % of
/// V (1 - n) / mean grain volume, the grain-size curve within the sampling bound, and settled
/// below the overlap tolerance (walls included).
inline void expect_packing_guarantees(const dem::PackingParams& in, const dem::PackingResult& r) {
  const double volume = psd::cylinder_volume(in.diameter, in.length);
  const double d_max = in.curve.d_max();
  EXPECT_NEAR(r.porosity, in.porosity, std::numbers::pi * d_max * d_max * d_max / 12 / volume);
  EXPECT_NEAR(static_cast<double>(r.count) / r.expected_count, 1.0, 0.05);
  EXPECT_LE(r.curve_deviation, r.curve_deviation_bound);
  EXPECT_TRUE(r.settled);
  EXPECT_LT(r.max_overlap, in.overlap_tolerance);
}

}  // namespace kolsky::testing
