// Unit tests of the benchmark tracking: JSON reading (Google Benchmark and LAMMPS formats), the
// mean-aggregate rule, ratios, the power-law fit, bench-check's comparison, and the frozen
// reference workload. Nothing here measures time: tests never depend on wall time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <fstream>
#include <string>

#include "reference_workload.hpp"
#include "summary/plot.hpp"
#include "summary/report.hpp"
#include "summary/results.hpp"

namespace kolsky::benchsum {
namespace {

using nlohmann::json;

// A Google Benchmark file as bench-check writes it: single runs then aggregates.
json bench_json(const std::string& date, double kernel_mean, double ref_mean, int version = 1) {
  json j;
  j["context"] = {{"date", date}, {"kind", "bench-check"}};
  j["benchmarks"] = json::array();
  const auto add = [&](const std::string& run, const std::string& agg, const std::string& counter, double v) {
    // cpu_time = real_time: per-CPU-second rates equal the wall ones in these literals.
    json b = {{"name", run + (agg.empty() ? "" : "_" + agg)}, {"run_name", run}, {"iterations", 3},
              {"real_time", 100.0}, {"cpu_time", 100.0}, {"threads", 1}, {counter, v}};
    b["run_type"] = agg.empty() ? "iteration" : "aggregate";
    if (!agg.empty()) b["aggregate_name"] = agg;
    if (counter == kReferenceCounter) b["reference_version"] = agg == "stddev" ? 0 : version;
    j["benchmarks"].push_back(b);
  };
  add("BM_DemCompaction/1/real_time", "", "particle_steps_per_s", 0.9 * kernel_mean);
  add("BM_DemCompaction/1/real_time", "", "particle_steps_per_s", 1.1 * kernel_mean);
  add("BM_Reference/1/iterations:3/real_time", "", kReferenceCounter, ref_mean);
  add("BM_DemCompaction/1/real_time", "mean", "particle_steps_per_s", kernel_mean);
  add("BM_DemCompaction/1/real_time", "stddev", "particle_steps_per_s", 0.1 * kernel_mean);
  add("BM_Reference/1/iterations:3/real_time", "mean", kReferenceCounter, ref_mean);
  add("BM_Reference/1/iterations:3/real_time", "stddev", kReferenceCounter, 1.0);
  return j;
}

TEST(BenchSummary, NormalizesRunNames) {
  EXPECT_EQ(normalize_key("BM_DemCompaction/1/real_time"), "BM_DemCompaction/1");
  EXPECT_EQ(normalize_key("BM_Reference/2/iterations:3/real_time"), "BM_Reference/2");
  EXPECT_EQ(normalize_key("BM_Chapter2Run/0/iterations:1/real_time"), "BM_Chapter2Run/0");
  EXPECT_EQ(normalize_key("BM_FeSpecimenStep/10/20"), "BM_FeSpecimenStep/10/20");
  EXPECT_EQ(normalize_key("BM_X/real_time/threads:2"), "BM_X/threads:2");
}

TEST(BenchSummary, ParsesFileNamesAndDates) {
  EXPECT_EQ(parse_file_name("20261122_b193267a4c12_bench_dem.json"),
            (std::pair<std::string, std::string>{"bench_dem", "b193267a4c12"}));
  EXPECT_EQ(parse_file_name("20261122_1716_lammps.json").first, "lammps");
  EXPECT_EQ(parse_file_name("20261122_lammps.json").first, "lammps");
  EXPECT_EQ(parse_file_name("notes.json").first, "");
  EXPECT_EQ(parse_iso_time("1970-01-02T00:00:00+00:00"), 86400);
  EXPECT_EQ(parse_iso_time("2026-11-22T13:04:39+01:00"), parse_iso_time("2026-11-22T12:04:39Z"));
  EXPECT_EQ(short_date(parse_iso_time("2026-11-22T16:53:00+00:00")), "2026-11-22 16:53");
  EXPECT_EQ(short_date(parse_iso_time("2024-02-29T23:59:59")), "2024-02-29 23:59");
  EXPECT_THROW(parse_iso_time("22/11/2026"), std::invalid_argument);
}

TEST(BenchSummary, TakesTheMeanAggregateElseTheMeanOfSingleRuns) {
  json j = bench_json("2026-12-01T10:00:00+00:00", 7e6, 1e8);
  const ResultFile f = parse_result(j, "20261201_0123456789ab_bench_dem.json");
  EXPECT_EQ(f.bench, "bench_dem");
  EXPECT_EQ(f.commit, "0123456789ab");
  EXPECT_EQ(f.kind, "bench-check");
  EXPECT_DOUBLE_EQ(*value(f, "BM_DemCompaction/1", "particle_steps_per_s"), 7e6);
  // Without aggregates: the mean of the single runs (0.9 and 1.1 x 7e6).
  json single = j;
  auto& b = single["benchmarks"];
  b.erase(std::remove_if(b.begin(), b.end(), [](const json& e) { return e["run_type"] == "aggregate"; }), b.end());
  const ResultFile g = parse_result(single, "20261201_0123456789ab_bench_dem.json");
  EXPECT_DOUBLE_EQ(*value(g, "BM_DemCompaction/1", "particle_steps_per_s"), 7e6);
  EXPECT_FALSE(value(g, "BM_DemCompaction/2", "particle_steps_per_s"));
}

TEST(BenchSummary, OldFilesWithoutRunNameAndWithoutReference) {
  json j;  // the shape of the files of 2026-11-22: no run_name on some, no reference
  j["context"] = {{"date", "2026-11-22T07:10:25+00:00"}};
  j["benchmarks"] = json::array({{{"name", "BM_DemCompaction/1/real_time_mean"}, {"run_type", "aggregate"},
                                  {"aggregate_name", "mean"}, {"particle_steps_per_s", 2.5e6}}});
  const ResultFile f = parse_result(j, "20261122_e08ae138cc49_bench_dem.json");
  EXPECT_DOUBLE_EQ(*value(f, "BM_DemCompaction/1", "particle_steps_per_s"), 2.5e6);
  EXPECT_FALSE(ratio(f, tracked()[0]));  // absolute only
}

TEST(BenchSummary, RatioNeedsKernelAndReferenceOfTheSameBench) {
  const ResultFile f = parse_result(bench_json("2026-12-01T10:00:00+00:00", 7e6, 1e8, 3), "20261201_0123456789ab_bench_dem.json");
  const auto r = ratio(f, tracked()[0]);
  ASSERT_TRUE(r);
  EXPECT_DOUBLE_EQ(r->ratio, 0.07);
  EXPECT_EQ(r->version, 3);
  EXPECT_FALSE(ratio(f, tracked()[1]));  // no 2-thread kernel nor reference in this file
  EXPECT_FALSE(ratio(f, tracked()[2]));  // the FE figure comes from bench_fe only
}

TEST(BenchSummary, EachBatchKernelVariantIsTrackedWhereTheRunHadIt) {
  // A run on a CPU without AVX-512: its BM_DemKernelVariant/2 was skipped, so it has no entry.
  json j = bench_json("2026-12-06T10:00:00+00:00", 7e6, 1e8);
  for (const auto& [name, rate] : {std::pair{"BM_DemKernelVariant/0/real_time", 5e6}, {"BM_DemKernelVariant/1/real_time", 6e6}})
    j["benchmarks"].push_back({{"name", std::string(name) + "_mean"}, {"run_name", name}, {"run_type", "aggregate"},
                               {"aggregate_name", "mean"}, {"iterations", 3}, {"real_time", 100.0},
                               {"cpu_time", 100.0}, {"threads", 1}, {"particle_steps_per_s", rate}});
  const ResultFile f = parse_result(j, "20261206_0123456789ab_bench_dem.json");
  const auto ratio_of = [&](const std::string& id) -> std::optional<Ratio> {
    for (const Tracked& t : tracked())
      if (t.id == id) return ratio(f, t);
    ADD_FAILURE() << "no tracked figure " << id;
    return std::nullopt;
  };
  EXPECT_DOUBLE_EQ(ratio_of("dem_portable")->ratio, 0.05);
  EXPECT_DOUBLE_EQ(ratio_of("dem_avx2")->ratio, 0.06);
  EXPECT_FALSE(ratio_of("dem_avx512"));
}

TEST(BenchSummary, CpuRateScalesWallRatesByRealOverCpuTime) {
  json j = bench_json("2026-12-01T10:00:00+00:00", 6e6, 1e8);
  for (auto& b : j["benchmarks"])  // the process had the core 2/3 of the time in the kernel
    if (b["run_name"] == "BM_DemCompaction/1/real_time") b["cpu_time"] = 100.0 / 1.5;
  const ResultFile f = parse_result(j, "20261201_0123456789ab_bench_dem.json");
  EXPECT_DOUBLE_EQ(*value(f, "BM_DemCompaction/1", "particle_steps_per_s"), 6e6);
  EXPECT_DOUBLE_EQ(*cpu_rate(f, "BM_DemCompaction/1", "particle_steps_per_s"), 9e6);
  EXPECT_DOUBLE_EQ(ratio(f, tracked()[0])->ratio, 0.09);  // dem_1t is per CPU second
  // A counter that is per CPU second already (no /real_time in the name) stays as it is.
  json fe;
  fe["context"] = {{"date", "2026-12-01T10:00:00+00:00"}};
  fe["benchmarks"] = json::array({{{"name", "BM_FeSpecimenStep/10/20"}, {"run_name", "BM_FeSpecimenStep/10/20"},
                                   {"run_type", "iteration"}, {"real_time", 30.0}, {"cpu_time", 20.0},
                                   {"elem_updates_per_s", 4e6}}});
  EXPECT_DOUBLE_EQ(*cpu_rate(parse_result(fe, "20261201_0123456789ab_bench_fe.json"), "BM_FeSpecimenStep/10/20",
                             "elem_updates_per_s"), 4e6);
}

// The 2-thread figure counts only when BM_Reference/2 ran at >= 1.9 x BM_Reference/1.
TEST(BenchSummary, TwoThreadFigureNeedsBothCores) {
  const auto file = [](double ref2) {
    json j = bench_json("2026-12-01T10:00:00+00:00", 7e6, 1e8);
    for (const std::string agg : {"", "mean"}) {
      json b = {{"name", "BM_DemCompaction/2/real_time"}, {"run_name", "BM_DemCompaction/2/real_time"},
                {"real_time", 1.0}, {"cpu_time", 1.0}, {"particle_steps_per_s", 1.4e7}};
      json r = {{"name", "BM_Reference/2/iterations:3/real_time"}, {"run_name", "BM_Reference/2/iterations:3/real_time"},
                {"real_time", 1.0}, {"cpu_time", 1.0}, {kReferenceCounter, ref2}, {"reference_version", 1}};
      for (json* e : {&b, &r}) {
        (*e)["run_type"] = agg.empty() ? "iteration" : "aggregate";
        if (!agg.empty()) (*e)["aggregate_name"] = agg;
      }
      j["benchmarks"].push_back(b);
      j["benchmarks"].push_back(r);
    }
    return parse_result(j, "20261201_0123456789ab_bench_dem.json");
  };
  const Tracked& two = tracked()[1];
  EXPECT_DOUBLE_EQ(*two_core_factor(file(1.95e8)), 1.95);
  EXPECT_TRUE(usable(file(1.95e8), two));
  EXPECT_FALSE(usable(file(1.84e8), two));
  EXPECT_FALSE(usable(file(0.65e8), two));
  EXPECT_TRUE(usable(file(0.65e8), tracked()[0]));  // the 1-thread figure does not care
  const auto rows = compare({file(2e8)}, {file(0.65e8)}, {{"dem_1t", 0.1}, {"dem_2t", 0.1}});
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NE(rows[1].skipped, "");
  EXPECT_FALSE(rows[1].regression);  // 0.215 against 0.07 would fail, but it is not compared
  EXPECT_NE(format_check(rows).find("second core busy"), std::string::npos);
  // A tracked file that lacked the second core is no baseline for the 2-thread figure.
  EXPECT_FALSE(compare({file(0.65e8)}, {file(2e8)}, {{"dem_1t", 0.1}, {"dem_2t", 0.1}})[1].base);
}

TEST(BenchSummary, ReadsLammpsRuns) {
  json j;
  j["context"] = {{"date", "2026-11-22T17:25:30+00:00"}};
  j["runs"] = json::array({{{"style", "hertz_history"}, {"ranks", 1}, {"particle_steps_per_s", 3.5e6}},
                           {{"style", "hertz_history"}, {"ranks", 1}, {"particle_steps_per_s", 4.1e6}},
                           {{"style", "granular"}, {"ranks", 1}, {"particle_steps_per_s", 3.3e6}}});
  j["summary"] = json::array({{{"style", "granular"}, {"ranks", 1}, {"median_particle_steps_per_s", 3.3e6}},
                              {{"style", "hertz_history"}, {"ranks", 1}, {"median_particle_steps_per_s", 3.8e6}}});
  const ResultFile f = parse_result(j, "20261122_1725_lammps.json");
  EXPECT_EQ(f.bench, "lammps");
  EXPECT_DOUBLE_EQ(*f.lammps_rate, 3.8e6);
  EXPECT_EQ(f.lammps_runs, 2);
  j["summary"] = json::array();
  EXPECT_THROW(parse_result(j, "20261122_1725_lammps.json"), std::runtime_error);
}

TEST(BenchSummary, FitsAPowerLaw) {
  std::vector<double> n = {1, 1.5, 2, 2.5, 3, 4}, y;
  for (double v : n) y.push_back(3.2 * std::pow(v, -4.3));
  const auto fit = fit_power_law(n, y);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->exponent, -4.3, 1e-12);
  EXPECT_NEAR(fit->prefactor, 3.2, 1e-12);
  EXPECT_EQ(fit->points, 6);
  EXPECT_FALSE(fit_power_law({2}, {1}));
  EXPECT_FALSE(fit_power_law({2, 2}, {1, 3}));         // one distinct x
  EXPECT_EQ(fit_power_law({1, 2, -1}, {1, 0.5, 7})->points, 2);  // non-positive x ignored
}

TEST(BenchSummary, CheckComparesWithTheNewestTrackedRatioOfTheSameVersion) {
  const std::string name = "20261201_0123456789ab_bench_dem.json";
  const std::vector<ResultFile> tracked_files = {
      parse_result(bench_json("2026-12-01T10:00:00+00:00", 7e6, 1e8), name),     // 0.07
      parse_result(bench_json("2026-12-01T11:00:00+00:00", 8e6, 1e8), name),     // 0.08, newest v1
      parse_result(bench_json("2026-12-01T12:00:00+00:00", 9e6, 1e8, 2), name)};  // other version
  const std::map<std::string, double> margins = {{"dem_1t", 0.10}};
  const auto at = [&](double kernel) {
    return compare(tracked_files, {parse_result(bench_json("2026-12-02T10:00:00+00:00", kernel, 1e8), "20261202_0123456789ab_bench_dem.json")},
                   margins);
  };
  const auto ok = at(7.3e6);  // -8.75 % of 0.08: within 10 %
  ASSERT_EQ(ok.size(), 1u);
  ASSERT_TRUE(ok[0].base);
  EXPECT_DOUBLE_EQ(ok[0].base->ratio, 0.08);
  EXPECT_FALSE(ok[0].regression);
  EXPECT_TRUE(at(7.1e6)[0].regression);  // -11.25 %
  EXPECT_NE(format_check(at(7.1e6)).find("SLOWER"), std::string::npos);
  const auto none = compare({}, {parse_result(bench_json("2026-12-02T10:00:00+00:00", 7e6, 1e8), "20261202_0123456789ab_bench_dem.json")}, margins);
  EXPECT_FALSE(none[0].base);
  EXPECT_FALSE(none[0].regression);
  EXPECT_THROW(compare(tracked_files, {tracked_files[0]}, {}), std::invalid_argument);  // no margin
}

TEST(BenchSummary, SpreadListsEveryRun) {
  const std::vector<ResultFile> runs = {parse_result(bench_json("2026-12-02T10:00:00+00:00", 7e6, 1e8), "20261202_0123456789ab_bench_dem.json"),
                                        parse_result(bench_json("2026-12-02T10:01:00+00:00", 8e6, 1e8), "20261202_1123456789ab_bench_dem.json")};
  const std::string s = format_spread(runs);
  EXPECT_NE(s.find("2 runs"), std::string::npos);
  EXPECT_NE(s.find("0.07000"), std::string::npos);
}

TEST(BenchSummary, ScriptPutsRatiosOnTheSecondAxisAndLabelsCommits) {
  Figure f;
  f.file = "x.png";
  f.xtics = {"abc1234", "def5678"};
  f.series = {{"rate", {0, 1}, {1, 2}, "linespoints", false}, {"ratio", {1}, {0.07}, "points", true},
              {"empty", {}, {}, "points", false}};
  const std::string gp = gnuplot_script(f);
  EXPECT_NE(gp.find("'abc1234' 0, 'def5678' 1"), std::string::npos);
  EXPECT_NE(gp.find("index 1 using 1:2 axes x1y2"), std::string::npos);
  EXPECT_EQ(gp.find("index 2"), std::string::npos);  // the empty series is left out
  f.file = "../x.png";
  EXPECT_THROW(gnuplot_script(f), std::invalid_argument);
}

// The Chapter 5 ensemble model (study_ch5_schedule --json) is read as a bench file and gets
// its own section: the newest file's table and one row per file over commits.
TEST(BenchSummary, EnsembleModelSectionFromTheNewestModelFile) {
  auto model = [](const std::string& date, double makespan16) {
    json j;
    j["context"] = {{"date", date}, {"kind", "model"}};
    j["benchmarks"] = json::array();
    for (const auto& [k, m] : {std::pair{1, 4877.0}, {16, makespan16}})
      j["benchmarks"].push_back({{"name", "BM_Ch5SetModel/" + std::to_string(k)},
                                 {"run_name", "BM_Ch5SetModel/" + std::to_string(k)},
                                 {"run_type", "iteration"}, {"iterations", 1}, {"real_time", m},
                                 {"cpu_time", m}, {"makespan_s", m}, {"critical_path_s", 1573.0},
                                 {"idle_fraction", k == 1 ? 0.0 : 0.81}});
    return j;
  };
  const std::vector<ResultFile> files = {
      parse_result(model("2026-12-05T10:00:00+00:00", 1800.0), "20261205_aaaaaaaaaaaa_bench_ch5_model.json"),
      parse_result(model("2026-12-06T10:00:00+00:00", 1573.0), "20261206_bbbbbbbbbbbb_bench_ch5_model.json")};
  EXPECT_EQ(files[0].bench, "bench_ch5_model");
  const std::string out = (std::filesystem::temp_directory_path() / "kolsky_bench_model").string();
  std::ostringstream log;
  write_summary(files, {}, out, "/nonexistent/gnuplot", log);
  std::ifstream in(out + "/README.md");
  const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("Newest, `20261206_bbbbbbbbbbbb_bench_ch5_model.json`"), std::string::npos) << md;
  EXPECT_NE(md.find("| 16 | 26.2 | 26.2 | 81 % |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `aaaaaaaaaaaa` | 2026-12-05 10:00 | 81.3 | 30.0 | 26.2 |"), std::string::npos) << md;
  std::filesystem::remove_all(out);
}

// Every tracked file parses, and the upscaling exponent of b193267 follows from its means:
// -4.30 (docs/dem.md quotes -4.33, fitted to the medians of the same file).
TEST(BenchSummary, TrackedResultsParse) {
  std::vector<std::string> skipped;
  const auto files = read_results_dir(std::string(KOLSKY_SOURCE_DIR) + "/benchmarks/results", skipped);
  EXPECT_TRUE(skipped.empty()) << skipped.front();
  bool seen = false;
  for (const ResultFile& f : files) {
    if (f.name != "20261122_b193267a4c12_bench_dem.json") continue;
    seen = true;
    std::vector<double> n, y;
    for (const UpscalePoint& p : upscale_series(f)) {
      n.push_back(p.n);
      y.push_back(p.s_per_sim_us);
    }
    ASSERT_EQ(n.size(), 6u);
    EXPECT_NEAR(fit_power_law(n, y)->exponent, -4.3015, 0.0005);
  }
  EXPECT_TRUE(seen);
}

// The reference workload is frozen: its network and the state after 10 steps must not move.
// If this fails after an intended change, increment kReferenceVersion and update the numbers.
TEST(BenchSummary, ReferenceWorkloadIsFrozen) {
  using namespace kolsky::bench;
  EXPECT_EQ(kReferenceVersion, 1);
  const ReferenceNetwork& net = reference_network();
  ASSERT_EQ(net.partner.size(), 138000u);
  EXPECT_EQ(net.partner[0], 20u);
  EXPECT_EQ(net.partner[137999], 24u);  // node 34499's last partner, wrapped
  ReferenceState s(net);
  for (int k = 0; k < 10; ++k) reference_step(net, s);
  // Same value at -O0 and -O3 with GCC 12; the tolerance allows another compiler's rounding.
  EXPECT_NEAR(reference_checksum(net, s), 5.1087653548385044, 1e-12 * 5.11);
}

}  // namespace
}  // namespace kolsky::benchsum
