// Unit tests for the reproduction harness: targets.json validation, scoring rules (scalar band
// and tolerance, trends, curves with x shift, worst point, known deviations, missing
// measurements) and the files write_report produces.
#include "core/errors.hpp"
#include "harness/report.hpp"
#include "io/csv.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace kolsky::harness;
using nlohmann::json;

namespace {

struct TempDir : kolsky::testing::TempDir {
  TempDir() : kolsky::testing::TempDir("kolsky_test_harness") {}
};


std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

json scalar_entry(const std::string& id, json band_or_tol, bool is_band = true) {
  json e = {{"id", id},
            {"kind", "scalar"},
            {"unit", "MPa"},
            {"reference", {{"value", 100.0}, {"source", "Sec. 4.4.1"}}},
            {"why_band", "experimental scatter"},
            {"status", "expected_pass"}};
  e[is_band ? "band" : "tolerance"] = std::move(band_or_tol);
  return e;
}

json curve_entry(const std::string& id, json points, json tolerance) {
  return {{"id", id},
          {"kind", "curve"},
          {"unit", "MPa"},
          {"reference", {{"points", std::move(points)}, {"source", "Fig. 2.5"}}},
          {"tolerance", std::move(tolerance)},
          {"why_band", "digitizing error"},
          {"status", "expected_pass"}};
}

TargetSet parse(const std::vector<json>& entries, const std::string& repo_root = "") {
  return parse_targets({{"set", "unit"}, {"targets", entries}}, "targets.json", repo_root);
}

/// The InputError path produced by parsing `entries`, or "" if it parses.
std::string error_path(const std::vector<json>& entries) {
  try {
    parse(entries);
  } catch (const kolsky::InputError& e) {
    EXPECT_EQ(e.file(), "targets.json");
    return e.path();
  }
  return "";
}

/// A smooth step whose position matters: y = 50 (1 + tanh((x - x0) / 0.05)).
double step(double x, double x0) { return 50.0 * (1.0 + std::tanh((x - x0) / 0.05)); }

}  // namespace

TEST(HarnessScalar, BandPassAndFail) {
  const TargetSet ts = parse({scalar_entry("s", {{"lo", 90}, {"hi", 110}})});
  Measurements in, out;
  in.scalar("s", 109.9);
  out.scalar("s", 110.5);
  const Score a = score_target(ts.targets[0], in);
  EXPECT_TRUE(a.pass);
  EXPECT_DOUBLE_EQ(*a.lo, 90.0);
  EXPECT_DOUBLE_EQ(*a.hi, 110.0);
  EXPECT_FALSE(score_target(ts.targets[0], out).pass);
  EXPECT_TRUE(score_target(ts.targets[0], out).fails_set());
}

TEST(HarnessScalar, ToleranceIntervalIsReported) {
  // ref 100, rtol 0.05, atol 1 -> [94, 106]
  const TargetSet ts = parse({scalar_entry("s", {{"rtol", 0.05}, {"atol", 1.0}}, false)});
  Measurements in, out, nan;
  in.scalar("s", 105.9);
  out.scalar("s", 106.1);
  nan.scalar("s", std::nan(""));
  const Score a = score_target(ts.targets[0], in);
  EXPECT_TRUE(a.pass);
  EXPECT_DOUBLE_EQ(*a.lo, 94.0);
  EXPECT_DOUBLE_EQ(*a.hi, 106.0);
  EXPECT_FALSE(score_target(ts.targets[0], out).pass);
  EXPECT_FALSE(score_target(ts.targets[0], nan).pass);
}

TEST(HarnessScalar, RangeReferenceWidenedByTolerance) {
  json e = scalar_entry("s", {{"rtol", 0.1}}, false);
  e["reference"] = {{"range", {10, 20}}, {"source", "Sec. 1.5"}};
  const TargetSet ts = parse({e});
  Measurements m;
  m.scalar("s", 21.5);
  const Score s = score_target(ts.targets[0], m);
  EXPECT_DOUBLE_EQ(*s.lo, 9.0);
  EXPECT_DOUBLE_EQ(*s.hi, 22.0);
  EXPECT_TRUE(s.pass);
}

TEST(HarnessTrend, PassesWhenItHolds) {
  json e = {{"id", "t"}, {"kind", "trend"}, {"unit", "-"},
            {"reference", {{"statement", "peak stress rises with moisture"}, {"source", "Sec. 2.4"}}},
            {"why_band", "qualitative statement"}, {"status", "expected_pass"}};
  const TargetSet ts = parse({e});
  Measurements yes, no;
  yes.trend("t", true, "41 MPa at 7% > 33 MPa at 3%");
  no.trend("t", false, "41 MPa at 7% < 45 MPa at 3%");
  const Score a = score_target(ts.targets[0], yes), b = score_target(ts.targets[0], no);
  EXPECT_TRUE(a.pass);
  EXPECT_EQ(*a.value, 1.0);
  EXPECT_EQ(*a.lo, 1.0);
  EXPECT_EQ(*a.hi, 1.0);
  EXPECT_NE(a.note.find("41 MPa"), std::string::npos);
  EXPECT_FALSE(b.pass);
  EXPECT_EQ(*b.value, 0.0);
}

// A trend's threshold: finite numbers by name, else refused with its JSON path; reading a missing
// target or key is an error naming the file, the target and the key (docs/reproductions.md).
TEST(HarnessTrend, ThresholdParsedRefusedAndRead) {
  const json e = {{"id", "t"}, {"kind", "trend"}, {"unit", "-"}, {"reference", {{"source", "Sec. 5.3.1"}}},
                  {"threshold", {{"max_rms_pa", 2e6}}}, {"why_band", "RMS <= 2 MPa"}, {"status", "expected_pass"}};
  const TargetSet ts = parse({e});
  EXPECT_EQ(threshold(ts, "t", "max_rms_pa"), 2e6);
  auto with = [](json entry, json thr) { entry["threshold"] = std::move(thr); return entry; };
  EXPECT_EQ(error_path({with(e, {{"max_rms_pa", "2e6"}})}), "targets[0].threshold.max_rms_pa");
  EXPECT_EQ(error_path({with(e, {{"max_rms_pa", NAN}})}), "targets[0].threshold.max_rms_pa");
  EXPECT_EQ(error_path({with(e, json::object())}), "targets[0].threshold");
  EXPECT_EQ(error_path({with(e, 2e6)}), "targets[0].threshold");
  EXPECT_EQ(error_path({with(scalar_entry("s", {{"lo", 0}, {"hi", 1}}), {{"k", 1}})}), "targets[0].threshold");
  auto read_error = [&](const std::string& id) -> std::string {
    try { threshold(ts, id, "min_ratio"); } catch (const kolsky::InputError& err) { return err.what(); }
    return "no error";
  };
  EXPECT_EQ(read_error("t"), "targets.json: targets[0].threshold.min_ratio: required field is missing "
                             "(target 't': the driver's rule reads it)");
  EXPECT_EQ(read_error("nope"),
            "targets.json: targets: no target 'nope', whose threshold 'min_ratio' the driver reads");
}

// The Chapter 5 driver measures two parts on two threads and merges them: every value and
// note must arrive, and an id measured by both parts is a driver bug, not a silent overwrite.
TEST(HarnessMeasurements, MergeKeepsValuesAndNotesAndRefusesDuplicates) {
  Measurements whole, part;
  whole.scalar("a", 1.5);
  whole.note("a", "first");
  part.trend("b", true, "holds");
  part.note("a", "second");
  part.note("b", "why");
  whole.merge(part);
  ASSERT_NE(whole.find("b"), nullptr);
  EXPECT_TRUE(whole.find("b")->holds);
  EXPECT_EQ(whole.find("a")->value, 1.5);
  EXPECT_EQ(whole.note_for("a"), "first; second");
  EXPECT_EQ(whole.note_for("b"), "why");
  Measurements clash;
  clash.scalar("a", 2.0);
  EXPECT_THROW(whole.merge(clash), std::invalid_argument);
}

TEST(HarnessCurve, XShiftWithinXtolPassesAndWithoutFails) {
  Curve measured;
  for (int i = 0; i <= 200; ++i) {
    measured.x.push_back(i * 0.005);
    measured.y.push_back(step(measured.x.back(), 0.51));  // the measured step is 0.01 late
  }
  json points = json::array();
  for (double x = 0.1; x < 0.95; x += 0.05) points.push_back({x, step(x, 0.50)});
  const TargetSet ts = parse({curve_entry("shifted", points, {{"rtol", 0.02}, {"atol", 0.5}, {"xtol", 0.015}}),
                              curve_entry("strict", points, {{"rtol", 0.02}, {"atol", 0.5}})});
  Measurements m;
  m.curve("shifted", measured);
  m.curve("strict", measured);
  const Score shifted = score_target(ts.targets[0], m), strict = score_target(ts.targets[1], m);
  EXPECT_TRUE(shifted.pass) << shifted.note;
  EXPECT_FALSE(strict.pass);
  ASSERT_TRUE(strict.worst);
  EXPECT_NEAR(strict.worst->x_ref, 0.5, 0.03);  // the steepest part suffers most from the shift
  EXPECT_GT(*strict.value, *strict.hi);
  EXPECT_LE(*shifted.value, *shifted.hi);
}

TEST(HarnessCurve, WorstPointIsFound) {
  const Curve line{{0.0, 1.0}, {0.0, 1.0}};  // y = x
  const Curve ref{{0.2, 0.5, 0.8}, {0.2, 0.6, 0.81}};
  const CurveCheck cc = compare_curve(line, ref, {0.0, 0.05, 0.0});
  EXPECT_FALSE(cc.pass);
  EXPECT_EQ(cc.n_failed, 1u);
  ASSERT_TRUE(cc.worst);
  EXPECT_DOUBLE_EQ(cc.worst->x_ref, 0.5);
  EXPECT_NEAR(cc.worst->y_nearest, 0.5, 1e-12);
  EXPECT_NEAR(cc.worst->error, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(cc.worst->allowed, 0.05);

  const TargetSet ts = parse({curve_entry("c", {{0.2, 0.2}, {0.5, 0.6}, {0.8, 0.81}}, {{"atol", 0.05}})});
  Measurements m;
  m.curve("c", line);
  const Score s = score_target(ts.targets[0], m);
  EXPECT_NEAR(*s.value, 0.1 / 0.6, 1e-12);  // relative error at the worst point
  EXPECT_NEAR(*s.hi, 0.05 / 0.6, 1e-12);
  EXPECT_NE(s.note.find("relative error"), std::string::npos);
}

TEST(HarnessCurve, UnloadingBranchAndOutOfRangePoints) {
  // Load to x = 1 and unload back to x = 0.6: y at x = 0.8 is either 0.8 (loading) or 1.2.
  const Curve loop{{0.0, 1.0, 0.6}, {0.0, 1.0, 1.4}};
  EXPECT_TRUE(compare_curve(loop, {{0.8}, {1.2}}, {0.0, 1e-9, 0.0}).pass);
  EXPECT_FALSE(compare_curve(loop, {{0.8}, {1.0}}, {0.0, 1e-9, 0.0}).pass);
  EXPECT_TRUE(compare_curve(loop, {{0.8}, {0.8}}, {0.0, 1e-9, 0.0}).pass);
  const CurveCheck outside = compare_curve(loop, {{1.2}, {1.0}}, {0.0, 0.1, 0.1});
  EXPECT_FALSE(outside.pass);
  ASSERT_TRUE(outside.worst);
  EXPECT_TRUE(outside.worst->outside);

  const TargetSet ts = parse({curve_entry("c", {{0.5, 0.5}, {1.5, 1.0}}, {{"atol", 0.1}})});
  Measurements m;
  m.curve("c", loop);
  const Score s = score_target(ts.targets[0], m);
  EXPECT_FALSE(s.pass);
  EXPECT_NE(s.note.find("outside the measured x range"), std::string::npos) << s.note;
}

TEST(HarnessStatus, KnownDeviationPassingIsFlaggedUnexpected) {
  json e = scalar_entry("k", {{"lo", 90}, {"hi", 110}});
  e["status"] = "known_deviation";
  e["reason"] = "EOS not calibrated yet";
  const TargetSet ts = parse({e});
  Measurements pass, fail;
  pass.scalar("k", 100);
  fail.scalar("k", 200);
  const Score p = score_target(ts.targets[0], pass), f = score_target(ts.targets[0], fail);
  EXPECT_TRUE(p.unexpected_pass);
  EXPECT_NE(p.note.find("remove"), std::string::npos);
  EXPECT_FALSE(f.pass);
  EXPECT_FALSE(f.unexpected_pass);
  EXPECT_FALSE(f.fails_set());
}

TEST(HarnessStatus, MissingOrMiskindedMeasurementFails) {
  const TargetSet ts = parse({scalar_entry("s", {{"lo", 0}, {"hi", 1}})});
  Measurements none, wrong;
  const Score a = score_target(ts.targets[0], none);
  EXPECT_FALSE(a.pass);
  EXPECT_FALSE(a.measured);
  EXPECT_NE(a.note.find("not measured"), std::string::npos);
  wrong.trend("s", true, "oops");
  EXPECT_FALSE(score_target(ts.targets[0], wrong).pass);
  EXPECT_THROW(wrong.trend("s", true, "again"), std::invalid_argument);
}

TEST(HarnessTargets, ValidationErrorsNameTheEntryPath) {
  const json ok = scalar_entry("a", {{"lo", 0}, {"hi", 1}});
  auto with = [&](const std::string& key, json value) {
    json e = ok;
    e["id"] = "b";
    if (value.is_null()) e.erase(key);
    else e[key] = std::move(value);
    return e;
  };
  EXPECT_EQ(error_path({ok}), "");
  EXPECT_EQ(error_path({ok, with("band", {{"lo", 2}, {"hi", 1}})}), "targets[1].band");
  EXPECT_EQ(error_path({ok, with("band", {{"lo", 0}})}), "targets[1].band.hi");
  EXPECT_EQ(error_path({ok, with("band", nullptr)}), "targets[1].band");
  EXPECT_EQ(error_path({ok, with("why_band", nullptr)}), "targets[1].why_band");
  EXPECT_EQ(error_path({ok, with("kind", "surface")}), "targets[1].kind");
  EXPECT_EQ(error_path({ok, with("status", "maybe")}), "targets[1].status");
  EXPECT_EQ(error_path({ok, with("status", "known_deviation")}), "targets[1].reason");
  EXPECT_EQ(error_path({ok, with("tolerence", {{"rtol", 0.1}})}), "targets[1].tolerence");
  EXPECT_EQ(error_path({ok, with("reference", {{"value", 1}})}), "targets[1].reference.source");
  EXPECT_EQ(error_path({ok, with("id", "a")}), "targets[1].id");
  EXPECT_EQ(error_path({curve_entry("c", {{0, 1}, {2}}, {{"rtol", 0.1}})}),
            "targets[0].reference.points[1]");
  EXPECT_EQ(error_path({curve_entry("c", {{0, 1}}, {{"xtol", 0.1}})}), "targets[0].tolerance");
}

TEST(HarnessTargets, CurveReferenceLoadedFromCsvRelativeToRepoRoot) {
  TempDir root;
  fs::create_directories(root.str() + "/data/digitized");
  kolsky::io::CsvTable table;
  table.header = {"strain", "stress_mpa"};
  table.columns = {{0.0, 0.01, 0.02}, {0.0, 5.0, 12.0}};
  kolsky::io::write_csv(root.file("data/digitized/ss.csv"), table, "Fig. 2.5");
  json e = curve_entry("c", nullptr, {{"rtol", 0.1}});
  e["reference"] = {{"file", "data/digitized/ss.csv"}, {"x", "strain"}, {"y", "stress_mpa"},
                    {"source", "Fig. 2.5"}};
  const TargetSet ts = parse({e}, root.str());
  EXPECT_EQ(ts.targets[0].reference.points.y, (std::vector<double>{0.0, 5.0, 12.0}));
  e["reference"]["y"] = "stress";
  try {
    parse({e}, root.str());
    FAIL() << "expected InputError";
  } catch (const kolsky::InputError& err) {
    EXPECT_EQ(err.path(), "targets[0].reference");
    EXPECT_NE(err.rule().find("stress_mpa"), std::string::npos) << err.what();
  }
}

TEST(HarnessReport, WritesResultsJsonAndReportWithFailMarker) {
  TempDir dir;
  json good = scalar_entry("good", {{"lo", 90}, {"hi", 110}});
  json bad = scalar_entry("bad", {{"lo", 90}, {"hi", 110}});
  json known = scalar_entry("known", {{"lo", 90}, {"hi", 110}});
  known["status"] = "known_deviation";
  known["reason"] = "not calibrated | yet";
  json curve = curve_entry("curve", {{0.2, 0.2}, {0.5, 0.6}}, {{"atol", 0.05}});
  std::ofstream(dir.file("targets.json")) << json{{"set", "demo"}, {"targets", {good, bad, known, curve}}}.dump(2);

  ReportInput in;
  in.set = "demo";
  in.scale = "smoke";
  in.targets_path = dir.file("targets.json");
  in.out_dir = dir.file("out");
  in.wall_time_s = 1.5;
  in.gnuplot = "";  // plotting disabled: the report must say so instead of failing
  in.m.scalar("good", 100);
  in.m.scalar("bad", 150);
  in.m.scalar("known", 150);
  in.m.curve("curve", {{0.0, 1.0}, {0.0, 1.0}});
  in.m.scalar("typo", 1.0);
  in.m.note("good", "from gauge pair 1");
  in.plots.push_back({"demo.png", "Demo", "x", "y", {{"line", {0, 1}, {0, 1}}}, {}, {}, false, false});
  EXPECT_EQ(write_report(in), 2);  // bad and curve; the known deviation does not count

  const json r = json::parse(read_text(dir.file("out/results.json")));
  std::vector<std::string> keys;
  for (const auto& [k, v] : r.items()) keys.push_back(k);
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(keys, (std::vector<std::string>{"git_commit", "scale", "set", "targets", "wall_time_s"}));
  EXPECT_EQ(r["set"], "demo");
  EXPECT_EQ(r["wall_time_s"], 1.5);
  ASSERT_EQ(r["targets"].size(), 4u);
  for (const json& t : r["targets"])
    for (const char* k : {"id", "value", "lo", "hi", "reference", "unit", "source", "status", "pass"})
      EXPECT_TRUE(t.contains(k)) << k << " missing in " << t.dump();
  EXPECT_EQ(r["targets"][0]["pass"], true);
  EXPECT_EQ(r["targets"][0]["reference"]["value"], 100.0);
  EXPECT_EQ(r["targets"][1]["pass"], false);
  EXPECT_TRUE(r["targets"][3].contains("worst_point"));

  const std::string md = read_text(dir.file("out/report.md"));
  EXPECT_NE(md.find("<span style=\"color:red\">FAIL</span>"), std::string::npos);
  EXPECT_NE(md.find("<span style=\"color:green\">PASS</span>"), std::string::npos);
  EXPECT_NE(md.find("not calibrated \\| yet"), std::string::npos);  // escaped inside the table
  EXPECT_NE(md.find("plot not generated"), std::string::npos);
  EXPECT_NE(md.find("Worst points"), std::string::npos);
  EXPECT_NE(md.find("`typo`"), std::string::npos);  // measured but no such target
  EXPECT_TRUE(fs::exists(dir.file("out/plots_src/demo.gp")));
  EXPECT_TRUE(fs::exists(dir.file("out/plots_src/demo.dat")));

  in.set = "other";
  EXPECT_THROW(write_report(in), kolsky::InputError);
}

TEST(HarnessReport, GnuplotRendersPngWithBandsAndPoints) {
  const std::string gnuplot = default_gnuplot();
  if (gnuplot.empty() || access(gnuplot.c_str(), X_OK) != 0) GTEST_SKIP() << "no gnuplot";
  TempDir dir;
  Plot p;
  p.file = "stress_strain.png";
  p.title = "Stress-strain (it's a test_with_underscores)";
  p.xlabel = "strain";
  p.ylabel = "stress [MPa]";
  p.series.push_back({"simulated", {0, 0.01, 0.02}, {0, 5, 12}, "lines"});
  p.bands.push_back({"tolerance", {0, 0.01, 0.02}, {0, 4, 10}, {0, 6, 14}});
  p.reference_points.push_back({"Song 2009", {0.01, 0.02}, {5.5, 11}, {0.5, 1.0}, {}});
  // Points named one by one (the Chapter 5 speed figure labels each with its N).
  p.reference_points.push_back({"named", {0.005, 0.015}, {3, 8}, {}, {"N = 1.5", "it's N = 2"}});
  const PlotResult res = render_plot(p, dir.str(), gnuplot);
  ASSERT_TRUE(res.ok) << res.message;
  EXPECT_GT(fs::file_size(dir.file("stress_strain.png")), 1000u);
  const std::string gp = read_text(dir.file("plots_src/stress_strain.gp"));
  EXPECT_NE(gp.find("pngcairo size 900,600"), std::string::npos);
  EXPECT_NE(gp.find("filledcurves"), std::string::npos);
  EXPECT_NE(gp.find("yerrorbars"), std::string::npos);
  EXPECT_NE(gp.find("set label 'N = 1.5' at 0.005,3 offset"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set label 'it''s N = 2' at 0.015,8 offset"), std::string::npos) << gp;
  p.reference_points.back().point_labels.pop_back();  // one label for two points
  EXPECT_THROW(render_plot(p, dir.str(), gnuplot), std::invalid_argument);
  EXPECT_THROW(render_plot({"../escape.png", "", "", "", {}, {}, {}, false, false}, dir.str(), gnuplot),
               std::invalid_argument);
}
