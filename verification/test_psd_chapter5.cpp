// The Chapter 5 reconstructions (data/digitized/chapter5/): the grain-size curves deliver what
// they were fitted to (the printed particle counts at the stated geometry and porosity, read
// with the solver's within-bin model), their .meta.json properties are the curves' own, and
// the strain-rate histories peak and integrate (Eq. 5.1) as their .meta.json says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "psd/grain_size_curve.hpp"
#include "scene/csv_load.hpp"

namespace kolsky::psd {
namespace {

const std::string kDir = std::string(KOLSKY_SOURCE_DIR) + "/data/digitized/chapter5/";

GrainSizeCurve curve(const std::string& name) {
  const auto c = scene::read_two_column_csv(kDir + name, "diameter_m", "percent_passing");
  GrainSizeCurve g{c.x, c.y};
  g.validate();
  return g;
}

nlohmann::json meta(const std::string& name) {
  std::ifstream f(kDir + name);
  return nlohmann::json::parse(f);
}

double cylinder(double d, double l) { return std::numbers::pi / 4 * d * d * l; }

TEST(PsdChapter5, WangCurveGivesThePrintedCounts) {
  const auto g = curve("wang2018_psd_reconstructed.csv");
  const auto m = meta("wang2018_psd_reconstructed.meta.json");
  const double v = cylinder(0.015, 0.005);
  const double n1 = expected_particle_count(g, v, 0.41), n15 = expected_particle_count(upscale(g, 1.5), v, 0.41);
  // The scale was solved to the printed 43,642 and rounded to 4 digits: within 0.1 %.
  EXPECT_NEAR(n1 / 43642, 1.0, 1e-3);
  EXPECT_NEAR(n1, m["counts"]["at_N_1"].get<double>(), 1.0);
  EXPECT_NEAR(n15, m["counts"]["at_N_1.5"].get<double>(), 1.0);
  // The text's N = 1.5 count is 0.86 % below the pure N^-3 shift (meta: a property of the
  // text's packings); the curve's shift is exact.
  EXPECT_NEAR(n15 / n1, std::pow(1.5, -3), 1e-9);
  EXPECT_NEAR(percentile_diameter(g, 50) / m["properties"]["d50_m"].get<double>(), 1.0, 2e-3);
  EXPECT_NEAR(mean_volume_diameter(g) / m["properties"]["mean_volume_diameter_m"].get<double>(), 1.0, 2e-3);
  // targets.md 5d derives 0.284 mm from the printed count.
  EXPECT_NEAR(mean_volume_diameter(g) / 0.284e-3, 1.0, 5e-3);
}

TEST(PsdChapter5, HuangCurvesGiveThePrintedCountAndShareTheirScale) {
  const auto cut = curve("huang2013_psd_reconstructed.csv"), tail = curve("huang2013_psd_tail.csv");
  const auto m = meta("huang2013_psd_reconstructed.meta.json");
  const double n = expected_particle_count(upscale(cut, 2.5), cylinder(0.0372, 0.010), m["porosity"]["value"].get<double>());
  EXPECT_NEAR(n / 37595, 1.0, 1e-3);
  EXPECT_NEAR(n, m["counts"]["at_N_2.5_porosity_0.40"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(cut.diameter.front(), 1e-4);   // the cut (Sec. 5.3.2)
  EXPECT_DOUBLE_EQ(tail.diameter.front(), 1e-5);  // the tail's 0.01 mm
  EXPECT_NEAR(tail.diameter.back() / cut.diameter.back(), 1.0, 1e-6);
  // Above the cut the approximated curve is the tail curve renormalised: P_cut = (P - P0) / (1 - P0).
  const double p0 = passing_at(tail, 1e-4);
  EXPECT_GT(p0, 0.0);
  EXPECT_LT(p0, 5.0);
  for (double d : {2e-4, 4e-4, 6e-4})
    EXPECT_NEAR(passing_at(cut, d), 100 * (passing_at(tail, d) - p0) / (100 - p0), 0.3) << d;
}

TEST(PsdChapter5, StrainRateHistoriesPeakAndIntegrateAsDocumented) {
  const std::pair<const char*, std::pair<double, double>> cases[] = {
      {"wang2018_strain_rate_reconstructed.csv", {1200, 0.156}},
      {"huang2013_strain_rate_700_reconstructed.csv", {700, 0.196}}};
  for (const auto& [name, expect] : cases) {
    const auto t = scene::load_strain_rate_table(kDir + name);
    double peak = 0, strain = 0;
    for (std::size_t k = 0; k < t.x.size(); ++k) {
      peak = std::max(peak, t.y[k]);
      if (k > 0) strain += 0.5 * (t.y[k] + t.y[k - 1]) * (t.x[k] - t.x[k - 1]);
    }
    EXPECT_DOUBLE_EQ(peak, expect.first) << name;
    EXPECT_NEAR(strain, expect.second, 1e-6) << name;  // smoothstep halves integrate exactly
    EXPECT_DOUBLE_EQ(t.y.back(), 0.0) << name;
  }
}

}  // namespace
}  // namespace kolsky::psd
