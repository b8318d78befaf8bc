// The reconstructed Song et al. (2009) grain-size curve (data/digitized/chapter4/): the CSV is the
// documented Weibull model, and it delivers what the reconstruction was calibrated to (D50,
// d_max, poorly graded, and 34,411 particles at N = 2, porosity 0.44, Sec. 4.3). Targets, bands
// and specimen numbers come from the data files (meta.json, reported.json), not from this code.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "psd/grain_size_curve.hpp"
#include "psd/sampling.hpp"
#include "test_support.hpp"

namespace kolsky::psd {
namespace {

using kolsky::testing::record;
using nlohmann::json;

const std::string kDir = std::string(KOLSKY_SOURCE_DIR) + "/data/digitized/chapter4/";

json read_json(const std::string& name) {
  std::ifstream f(kDir + name);
  if (!f) throw std::runtime_error("cannot open " + kDir + name);
  return json::parse(f);
}

// The two-column CSV as the data folder writes it: '#' comments, one header row, then numbers.
GrainSizeCurve read_curve(const std::string& name) {
  std::ifstream f(kDir + name);
  if (!f) throw std::runtime_error("cannot open " + kDir + name);
  GrainSizeCurve c;
  std::string line;
  bool header = true;
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      EXPECT_EQ(line, "diameter_m,percent_passing");
      header = false;
      continue;
    }
    std::istringstream s(line);
    double d = 0, p = 0;
    char comma = 0;
    s >> d >> comma >> p;
    if (!s || comma != ',') throw std::runtime_error("bad row: " + line);
    c.diameter.push_back(d);
    c.percent_passing.push_back(p);
  }
  return c;
}

std::map<std::string, double> reported() {
  std::map<std::string, double> out;
  const json doc = read_json("reported.json");
  for (const auto& v : doc.at("values")) out[v.at("id")] = v.at("value").get<double>();
  return out;
}

struct Fixture {
  GrainSizeCurve curve = read_curve("song2009_psd_reconstructed.csv");
  json meta = read_json("song2009_psd_reconstructed.meta.json");
  std::map<std::string, double> ch4 = reported();
  double factor = meta.at("counts").at("upscale_factor").get<double>();
  double volume = cylinder_volume(ch4.at("ch4.specimen_diameter"), ch4.at("ch4.specimen_length"));

  const json& target(const std::string& id) const {
    for (const auto& t : meta.at("calibration_targets"))
      if (t.at("id") == id) return t;
    throw std::runtime_error("no calibration target " + id);
  }
  void expect_in_band(const std::string& id, double value) const {
    const auto& band = target(id).at("band");
    EXPECT_GE(value, band.at("lo").get<double>()) << id;
    EXPECT_LE(value, band.at("hi").get<double>()) << id;
    record(id, value);
  }
};

TEST(PsdSong, CsvIsTheDocumentedModel) {
  const Fixture fx;
  ASSERT_NO_THROW(fx.curve.validate());
  const auto& m = fx.meta.at("model");
  ASSERT_EQ(fx.curve.size(), m.at("n_rows").get<std::size_t>());
  const double dc = m.at("d_c_m"), k = m.at("m"), lo = m.at("d_min_m"), hi = m.at("d_max_m");
  auto weibull = [dc, k](double d) { return -std::expm1(-std::pow(d / dc, k)); };
  for (std::size_t i = 0; i < fx.curve.size(); ++i) {
    const double d = fx.curve.diameter[i];
    const double p = 100 * (weibull(d) - weibull(lo)) / (weibull(hi) - weibull(lo));
    // The CSV keeps 7 significant digits of d and 4 decimals of P: slope dP/dlnd < 60 %, so
    // 5e-7 relative in d is < 3e-5 points, plus 5e-5 of rounding.
    EXPECT_NEAR(fx.curve.percent_passing[i], p, 1e-4) << "row " << i + 1;
  }
  EXPECT_EQ(fx.curve.d_min(), lo);
  EXPECT_EQ(fx.curve.d_max(), hi);
}

TEST(PsdSong, HonoursD50DmaxAndGrading) {
  const Fixture fx;
  fx.expect_in_band("psd.song.d50", d50(fx.curve));
  fx.expect_in_band("psd.song.d_max", fx.curve.d_max());
  fx.expect_in_band("psd.song.c_u", uniformity_coefficient(fx.curve));
  // Recorded properties in the meta file are what the solver computes (5 significant digits).
  const auto& p = fx.meta.at("properties");
  EXPECT_NEAR(d50(fx.curve), p.at("d50_m").get<double>(), 1e-5 * d50(fx.curve));
  EXPECT_NEAR(d10(fx.curve), p.at("d10_m").get<double>(), 1e-4 * d10(fx.curve));
  EXPECT_NEAR(uniformity_coefficient(fx.curve), p.at("c_u").get<double>(), 1e-3);
  EXPECT_NEAR(mean_volume_diameter(fx.curve), p.at("mean_volume_diameter_m").get<double>(),
              1e-4 * mean_volume_diameter(fx.curve));
}

TEST(PsdSong, CountAtFactorTwoMatchesSec43) {
  const Fixture fx;
  const auto up = upscale(fx.curve, fx.factor);
  const double n44 = expected_particle_count(up, fx.volume, fx.ch4.at("ch4.porosity"));
  // The calibration target (the 5 % band around 34,411, from the data files).
  fx.expect_in_band("psd.song.count_n2", n44);
  EXPECT_NEAR(n44 / fx.ch4.at("ch4.particle_count"), 1.0, 0.05);
  // The meta file's recorded counts are the solver's, rounded to whole particles.
  const auto& c = fx.meta.at("counts");
  EXPECT_NEAR(n44, c.at("at_porosity_0.44").get<double>(), 0.5);
  EXPECT_NEAR(expected_particle_count(up, fx.volume, 0.45), c.at("at_porosity_0.45").get<double>(),
              0.5);
  record("count_n2_porosity_044", n44);
}

TEST(PsdSong, SampledSpecimenHasTheCount) {
  // A drawn N = 2 specimen: the count varies only through within-bin grain volumes (bins 5.3 %
  // wide, CV of grain volume about 5 %), relative std about 0.03 % at 34k grains; the issue's
  // 5 % band is the requirement.
  const Fixture fx;
  const auto up = upscale(fx.curve, fx.factor);
  const double vs = fx.volume * (1 - fx.ch4.at("ch4.porosity"));
  const auto s = sample_diameters(up, vs, 1);
  const auto& recorded = fx.meta.at("counts").at("sampled_at_porosity_0.44_seeds_1_2_3");
  EXPECT_EQ(static_cast<double>(s.size()), recorded.at(0).get<double>());  // same seed, same sample
  fx.expect_in_band("psd.song.count_n2", static_cast<double>(s.size()));
  EXPECT_LE(max_passing_deviation(up, s), max_passing_deviation_bound(up, vs));
  record("sample_max_dev_pp", max_passing_deviation(up, s));
}

}  // namespace
}  // namespace kolsky::psd
