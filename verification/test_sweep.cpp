// kolsky sweep (solver/sweep/): the values of a --set (lists, linear and log ranges, integer
// ranges as integers) and its refusals, the member product and its labels, every member's
// scene checked before any runs, a small sweep of a 1-D elastic scene giving one row per member
// (failed members recorded, the rest going on), the same table on one thread and on two and
// from the cache, the HDF5 table equal to the CSV one, and the figures' means and bars.
// No test reads a clock: run times are left out of every comparison.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "ensemble/ensemble.hpp"
#include "sweep/sweep_plots.hpp"
#include "sweep/sweep_run.hpp"
#include "sweep/sweep_table.hpp"
#include "test_support.hpp"

namespace kolsky::sweep {
namespace {

using kolsky::testing::input_error;
using kolsky::testing::TempDir;
using nlohmann::json;

// The CLI tests' scene: 1-D bars, a trapezoid pulse, a 10-element elastic column; ~1 ms a run.
std::string write_scene(const TempDir& dir) {
  const std::string path = dir.file("s.json");
  std::ofstream(path) << R"({"bars": {"incident": {"length": 2.0, "gauges": [1.0]},
                                       "transmission": {"length": 1.0, "gauges": [0.5]}},
    "pulse": {"kind": "trapezoid", "amplitude": 50e6, "rise_time": 20e-6, "duration": 100e-6, "fall_time": 20e-6},
    "specimen": {"model": "elastic", "constrained_modulus": 230e6, "n_elements": 10},
    "time": {"end": 0.6e-3}})";
  return path;
}

std::vector<ensemble::MemberResult> run(const SweepPlan& plan, const std::vector<SweepPoint>& points, int threads,
                              const std::string& cache = "") {
  ensemble::EnsembleOptions o;
  o.threads = threads;
  o.cache_dir = cache;
  return ensemble::run_ensemble(sweep_members(plan, points, {}), o);
}

// The table without its run times (the one column that differs between two runs).
SweepTable without_times(SweepTable t) {
  std::erase_if(t.columns, [](const Column& c) { return c.name == "run_s"; });
  return t;
}

TEST(Sweep, ValuesOfASet) {
  EXPECT_EQ(parse_axis("a.b=1e9:3e9:3").values, (std::vector<json>{1e9, 2e9, 3e9}));
  EXPECT_EQ(parse_axis("a.b=10:40:4").values, (std::vector<json>{10, 20, 30, 40}));  // integers
  EXPECT_TRUE(parse_axis("a.b=10:40:4").values[1].is_number_integer());
  EXPECT_TRUE(parse_axis("a.b=10:20:4").values[1].is_number_float());  // 13.33...: not whole
  EXPECT_TRUE(parse_axis("a.b=1.0:2.0:2").values[0].is_number_float());  // written as floats
  const SweepAxis lg = parse_axis("a.b=log:1e6:1e9:4");
  ASSERT_EQ(lg.values.size(), 4u);
  EXPECT_TRUE(lg.log_spaced);
  EXPECT_EQ(lg.values.front().get<double>(), 1e6);  // the ends as written
  EXPECT_EQ(lg.values.back().get<double>(), 1e9);
  EXPECT_NEAR(lg.values[1].get<double>(), 1e7, 1e-6);  // 1e6 x 1000^(1/3): rounding only
  EXPECT_EQ(parse_axis("a.b=5:5:1").values, (std::vector<json>{5}));
  EXPECT_EQ(parse_axis(R"(m=["elastic", "fe"])").values, (std::vector<json>{"elastic", "fe"}));
  EXPECT_EQ(parse_axis(R"(t="a:b")").values, (std::vector<json>{"a:b"}));  // a string, not a range
  EXPECT_EQ(parse_axis("x=-2e-3").values, (std::vector<json>{-2e-3}));     // one value
  EXPECT_EQ(parse_axis("x=-3:-1:3").values, (std::vector<json>{-3, -2, -1}));

  // Refused, naming --set, the key and the rule.
  for (const std::string bad : {"k=1:2:0", "k=1:2:-3", "k=1:2:2.5", "k=1:2", "k=1:2:3:4", "k=a:2:3", "k=1:inf:3",
                                "k=1:2:1", "k=log:0:1:3", "k=log:-1:1:3", "k=[]", "k=nope"}) {
    const InputError e = input_error([&] { parse_axis(bad); });
    EXPECT_EQ(e.file(), "--set") << bad;
    EXPECT_EQ(e.path(), "k") << bad;
  }
  EXPECT_NE(std::string(input_error([] { parse_axis("k=1:2:0"); }).what()).find("count"), std::string::npos);
  EXPECT_NE(std::string(input_error([] { parse_axis("k=[]"); }).what()).find("empty"), std::string::npos);
  const InputError no_eq = input_error([] { parse_axis("specimen.length"); });
  EXPECT_EQ(no_eq.path(), "specimen.length");
  EXPECT_NE(std::string(no_eq.what()).find("no '='"), std::string::npos);
}

TEST(Sweep, MembersAreTheProductFirstKeySlowestSeedFastest) {
  TempDir dir;
  const SweepPlan plan = make_plan(write_scene(dir), {parse_axis("a.x=[1,2]"), parse_axis(R"(b=["p","q","r"])")}, 2);
  const auto points = sweep_points(plan);
  ASSERT_EQ(points.size(), 12u);
  EXPECT_EQ(points[0].label, "a.x=1 b=p seed=1");
  EXPECT_EQ(points[1].label, "a.x=1 b=p seed=2");
  EXPECT_EQ(points[2].label, "a.x=1 b=q seed=1");
  EXPECT_EQ(points[11].label, "a.x=2 b=r seed=2");
  const json s = member_scene(plan, points[11]);
  EXPECT_EQ(s["a"]["x"], 2);
  EXPECT_EQ(s["b"], "r");
  EXPECT_EQ(s["specimen"]["seed"], 2);
  EXPECT_EQ(s["specimen"]["n_elements"], 10);  // the rest as the scene has it
  EXPECT_EQ(value_text(json(2e9)), "2e+09");
  EXPECT_EQ(value_text(json(0.25)), "0.25");

  // A key twice, or the seed key beside --seeds: refused.
  EXPECT_EQ(input_error([&] { make_plan(plan.scene_file, {parse_axis("a=1"), parse_axis("a=2")}, 0); }).path(), "a");
  EXPECT_EQ(input_error([&] { make_plan(plan.scene_file, {parse_axis("specimen.seed=[1,2]")}, 3); }).path(),
            "specimen.seed");
  // Only seeds: one member per seed.
  EXPECT_EQ(sweep_points(make_plan(plan.scene_file, {}, 3)).size(), 3u);
  // A product past 1e6 members is refused before it is built.
  const SweepPlan huge = make_plan(plan.scene_file, {parse_axis("a=1:2:1000000"), parse_axis("b=1:2:2")}, 0);
  EXPECT_NE(std::string(input_error([&] { sweep_points(huge); }).what()).find("2e+06 members"), std::string::npos);
}

TEST(Sweep, EveryMembersSceneIsCheckedBeforeAnyRuns) {
  TempDir dir;
  const std::string scene = write_scene(dir);
  // The second member's key is misspelt: refused by the scene reader, naming file, key and member.
  SweepPlan plan = make_plan(scene, {parse_axis("specimen.constrained_modulus=[1e8,2e8]"),
                                     parse_axis("specimen.n_elemnts=[10]")}, 0);
  InputError e = input_error([&] { validate_points(plan, sweep_points(plan)); });
  EXPECT_EQ(e.file(), scene);
  EXPECT_EQ(e.path(), "specimen.n_elemnts");
  EXPECT_NE(std::string(e.what()).find("unknown key"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("sweep member specimen.constrained_modulus=1e+08"), std::string::npos);
  // A value out of range in one member only (the last), and a path through a number.
  plan = make_plan(scene, {parse_axis("specimen.n_elements=[10,20,1]")}, 0);
  EXPECT_EQ(input_error([&] { validate_points(plan, sweep_points(plan)); }).path(), "specimen.n_elements");
  plan = make_plan(scene, {parse_axis("specimen.n_elements.x=[1]")}, 0);
  EXPECT_EQ(input_error([&] { validate_points(plan, sweep_points(plan)); }).path(), "specimen.n_elements.x");
  // --seeds on a specimen without packing: specimen.seed is not a key of an elastic column.
  plan = make_plan(scene, {}, 2);
  EXPECT_EQ(input_error([&] { validate_points(plan, sweep_points(plan)); }).path(), "specimen.seed");
  // A scene that cannot be read.
  EXPECT_EQ(input_error([&] { make_plan(dir.file("missing.json"), {}, 1); }).file(), dir.file("missing.json"));
}

TEST(Sweep, ATinySweepGivesOneRowPerMemberAndRecordsFailures) {
  TempDir dir;
  // The stiffest member exceeds the fixed step's stability limit (checks off): it blows up,
  // is recorded as a numerical failure, and the others run.
  const SweepPlan plan = make_plan(write_scene(dir),
                                   {parse_axis("specimen.constrained_modulus=[1e8,2e8,5e10]"),
                                    parse_axis("specimen.n_elements=[10,20]"), parse_axis("time.dt=1.2e-6"),
                                    parse_axis("time.check_stability=false"), parse_axis("time.end=3e-3")},
                                   0);
  const auto points = sweep_points(plan);
  validate_points(plan, points);
  const auto results = run(plan, points, 1);
  const SweepTable t = make_table(plan, points, results);
  ASSERT_EQ(t.rows, 6u);
  EXPECT_EQ(t.column("member").numbers, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(t.column("specimen.constrained_modulus").numbers, (std::vector<double>{1e8, 1e8, 2e8, 2e8, 5e10, 5e10}));
  EXPECT_EQ(t.column("specimen.n_elements").numbers, (std::vector<double>{10, 20, 10, 20, 10, 20}));
  EXPECT_TRUE(t.column("time.check_stability").text);
  EXPECT_EQ(t.column("status").texts, (std::vector<std::string>{"ok", "ok", "ok", "ok", "failed", "failed"}));
  EXPECT_EQ(t.column("failure_kind").texts[4], "numerical");
  EXPECT_NE(t.column("error").texts[5].find("non-finite"), std::string::npos) << t.column("error").texts[5];
  // The summary figures of kolsky run, per member; a stiffer column carries more stress.
  const Column& back = t.column("peak_stress_back_mpa");
  EXPECT_GT(back.numbers[2], back.numbers[0]);
  EXPECT_TRUE(std::isnan(back.numbers[4]));
  for (const char* f : {"peak_stress_front_mpa", "peak_strain", "w_incident_j", "dissipation_percent", "steps"})
    EXPECT_TRUE(std::isfinite(t.column(f).numbers[0])) << f;
  EXPECT_EQ(t.column("steps").numbers[0], 2501);  // 3 ms at 1.2 us

  // CSV: a header and one line per member; HDF5: the same columns back.
  write_table_csv(dir.file("t.csv"), t);
  write_table_hdf5(dir.file("t.h5"), t);
  std::ifstream in(dir.file("t.csv"));
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("member,specimen.constrained_modulus,specimen.n_elements,time.dt,", 0), 0u) << header;
  int lines = 0;
  while (std::getline(in, line)) ++lines;
  EXPECT_EQ(lines, 6);
  const SweepTable back_from_h5 = read_table_hdf5(dir.file("t.h5"));
  EXPECT_EQ(csv_text(back_from_h5), csv_text(t));
  EXPECT_EQ(back_from_h5.meta, t.meta);
}

TEST(Sweep, TheTableIsTheSameOnOneThreadOnTwoAndFromTheCache) {
  TempDir dir;
  const SweepPlan plan = make_plan(write_scene(dir), {parse_axis("specimen.constrained_modulus=1e8:4e8:4"),
                                                      parse_axis("specimen.n_elements=[10,30]")}, 0);
  const auto points = sweep_points(plan);
  const std::string serial = csv_text(without_times(make_table(plan, points, run(plan, points, 1))));
  EXPECT_EQ(csv_text(without_times(make_table(plan, points, run(plan, points, 2)))), serial);
  // Cached: the second pass runs nothing and gives the same table, run times included.
  const auto first = run(plan, points, 2, dir.file("cache"));
  const auto again = run(plan, points, 1, dir.file("cache"));
  for (const auto& r : again) EXPECT_TRUE(r.cached) << r.label;
  EXPECT_EQ(csv_text(make_table(plan, points, again)), csv_text(make_table(plan, points, first)));
  EXPECT_EQ(csv_text(without_times(make_table(plan, points, again))), serial);
  // The key follows the member's scene: another value, another key; the same, the same.
  EXPECT_NE(member_key(plan, points[0]), member_key(plan, points[1]));
  EXPECT_EQ(member_key(plan, points[0]), member_key(plan, sweep_points(plan)[0]));
}

TEST(Sweep, FiguresShowEachSeedAndTheMeanWithItsSpread) {
  SweepTable t;
  t.rows = 4;
  t.columns = {{"k", false, {1, 1, 2, 2}, {}}, {"seed", false, {1, 2, 1, 2}, {}},
               {"f", false, {1.0, 3.0, 5.0, 5.0}, {}}, {"status", true, {}, {"ok", "ok", "ok", "ok"}}};
  t.meta = {{"axes", json::array({{{"key", "k"}, {"values", {1, 2}}, {"log_spaced", true}}})},
            {"seeds", 2}, {"figures", {"f"}}};
  const auto figures = sweep_figures(t, "s.json");
  ASSERT_EQ(figures.size(), 1u);
  const plot::Plot& p = figures[0];
  EXPECT_EQ(p.file, "sweep_f.png");
  EXPECT_TRUE(p.logx);
  ASSERT_EQ(p.series.size(), 1u);
  EXPECT_EQ(p.series[0].y, (std::vector<double>{1, 3, 5, 5}));  // every member
  ASSERT_EQ(p.reference_points.size(), 1u);
  EXPECT_EQ(p.reference_points[0].y, (std::vector<double>{2, 5}));  // the means
  EXPECT_NEAR(p.reference_points[0].yerr[0], std::sqrt(2.0), 1e-15);  // sample sd of {1, 3}
  EXPECT_EQ(p.reference_points[0].yerr[1], 0);
  // A failed member is left out.
  t.columns[3].texts[1] = "failed";
  EXPECT_EQ(sweep_figures(t, "s.json")[0].reference_points[0].y[0], 1);
}

TEST(Sweep, TheTimeLeftIsEstimatedFromTheMembersRun) {
  EXPECT_LT(eta_seconds(5, 0, 10), 0);   // nothing run yet: no estimate
  EXPECT_EQ(eta_seconds(5, 0, 0), 0);
  EXPECT_EQ(eta_seconds(6, 3, 7), 14);   // 2 s a member
}

}  // namespace
}  // namespace kolsky::sweep

namespace kolsky::sweep {
namespace {

// A breakage-strength sweep is about the grain counts (Sec. 5.3): a DEM specimen's member
// reports them, and they obey the replacement's bookkeeping (each break: -1 + 14 grains,
// Table 5.3), so grains_end = grains_start + 13 (primary + secondary breaks).
TEST(Sweep, ADemMemberReportsItsGrainCountsAndBreaks) {
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/data/examples";
  std::ifstream f(dir + "/dem_breakage_example.json");
  json scene = json::parse(f);
  scene["specimen"]["breakage"]["sigma_lim0"] = 1e9;  // weak enough that grains break (66 + 54)
  const json out = run_scene(scene, dir + "/dem_breakage_example.json", dir, MemberOptions{});
  ASSERT_EQ(out.at("status"), "ok") << out.dump();
  const json& s = out.at("summary");
  const double start = s.at("grains_start"), end = s.at("grains_end");
  const double primary = s.at("broken_primary"), secondary = s.at("broken_secondary");
  EXPECT_GT(primary, 0);
  EXPECT_EQ(end, start + 13 * (primary + secondary));
  EXPECT_DOUBLE_EQ(s.at("grain_growth_ratio").get<double>(), end / start);
}

}  // namespace
}  // namespace kolsky::sweep
