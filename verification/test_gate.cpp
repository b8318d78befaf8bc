// The regression gate (reproductions/harness/baseline.*, gate.*, gate/kolsky_gate.cpp,
// common/perturb.hpp): the one-ulp scene perturbation, the tolerance rule of make_baseline,
// every verdict of the comparison, the strict baseline reader, the log digest, and the CLI's
// exit codes and table on a scratch repository.
#include "common/perturb.hpp"
#include "core/errors.hpp"
#include "harness/baseline.hpp"
#include "harness/gate.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include <sys/wait.h>

using namespace kolsky::harness;
namespace fs = std::filesystem;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

MeasurementsFile run(double scalar, bool trend, std::vector<double> y) {
  MeasurementsFile f{"fake", "smoke", "abc", {}};
  f.m.scalar("a.scalar", scalar);
  f.m.trend("a.trend", trend, "x > y");
  f.m.curve("a.curve", {{0.0, 1.0, 2.0}, std::move(y)});
  return f;
}

Baseline baseline_of(double spread) {
  return make_baseline(run(10.0, true, {0, 1, 2}), {run(10.0 + spread, true, {0, 1, 2 + spread})},
                       RebaselineRule{}, "test", "now");
}

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

TEST(Perturb, MovesEveryNonZeroFloatByOneUlpAndNothingElse) {
  const nlohmann::json scene = {{"a", 0.1}, {"n", 7}, {"zero", 0.0}, {"name", "x"},
                                {"list", {1.5, -2.5e9, 3}}, {"nested", {{"b", 200e9}}}};
  nlohmann::json p = scene;
  kolsky::repro::perturb_floats(p, 0);
  EXPECT_EQ(p, scene);  // seed 0: as written
  kolsky::repro::perturb_floats(p, 3);
  EXPECT_EQ(p["n"], 7);
  EXPECT_EQ(p["zero"].get<double>(), 0.0);
  EXPECT_EQ(p["name"], "x");
  EXPECT_EQ(p["list"][2], 3);
  for (auto [now, was] : {std::pair{p["a"].get<double>(), 0.1}, {p["list"][0].get<double>(), 1.5},
                          {p["list"][1].get<double>(), -2.5e9}, {p["nested"]["b"].get<double>(), 200e9}}) {
    EXPECT_NE(now, was);
    EXPECT_TRUE(std::nextafter(was, INFINITY) == now || std::nextafter(was, -INFINITY) == now);
  }
  nlohmann::json q = scene;
  kolsky::repro::perturb_floats(q, 3);
  EXPECT_EQ(p, q);  // deterministic in the seed
  int differ = 0;
  for (unsigned seed = 4; seed < 12; ++seed) {
    nlohmann::json r = scene;
    kolsky::repro::perturb_floats(r, seed);
    differ += r != p ? 1 : 0;
  }
  EXPECT_GT(differ, 0);  // other seeds pick other directions
}

TEST(Perturb, AValueAtTheEdgeOfItsRangeMovesInward) {
  kolsky::testing::TempDir dir("kolsky_test_perturb");
  std::ifstream in(std::string(KOLSKY_SOURCE_DIR) + "/data/examples/song2009_elastic.json");
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["time"]["safety_factor"] = 1.0;  // allowed range (0, 1]: half the seeds step it out
  scene["pulse"]["file"] = std::string(KOLSKY_SOURCE_DIR) + "/data/digitized/bars/song2009_incident_480_reconstructed.csv";
  std::ofstream(dir.file("scene.json")) << scene.dump();
  for (unsigned seed = 1; seed <= 8; ++seed) {
    const nlohmann::json p = kolsky::repro::read_scene_json(dir.file("scene.json"), seed);
    const double f = p["time"]["safety_factor"].get<double>();
    EXPECT_EQ(f, std::nextafter(1.0, 0.0)) << "seed " << seed;  // up is refused, so down
  }
  EXPECT_EQ(kolsky::repro::read_scene_json(dir.file("scene.json"), 0), scene);
}

TEST(Gate, ToleranceIsFactorTimesTheSpreadOverTheUlpFloor) {
  const Baseline b = baseline_of(1e-12);
  const RebaselineRule rule;
  const BaselineValue* s = b.find("a.scalar");
  ASSERT_NE(s, nullptr);
  EXPECT_DOUBLE_EQ(s->spread, (10.0 + 1e-12) - 10.0);
  EXPECT_DOUBLE_EQ(s->tol.atol, rule.factor * s->spread);
  EXPECT_DOUBLE_EQ(s->tol.rtol, rule.floor_ulps * kEps);
  EXPECT_NE(s->why.find("largest change"), std::string::npos);
  const BaselineValue* c = b.find("a.curve");
  EXPECT_EQ(c->spread_x, 0.0);  // x unchanged: floor only
  EXPECT_DOUBLE_EQ(c->tol.atol, rule.factor * ((2 + 1e-12) - 2.0));
  EXPECT_TRUE(b.find("a.trend")->gated);
  // Unchanged under perturbation: the floor alone.
  EXPECT_EQ(baseline_of(0.0).find("a.scalar")->tol.atol, rule.atol_floor);
}

TEST(Gate, RoundOffDependentValuesAreUngatedAndSaySo) {
  const Baseline b = make_baseline(run(1, true, {0, 1, 2}),
                                   {run(1, false, {0, 1, 2}), run(NAN, true, {0, 1, 2})}, RebaselineRule{}, "t", "n");
  EXPECT_FALSE(b.find("a.trend")->gated);
  EXPECT_NE(b.find("a.trend")->why.find("flips in 1 of 2"), std::string::npos);
  EXPECT_FALSE(b.find("a.scalar")->gated);
  MeasurementsFile short_curve = run(1, true, {0, 1, 2});
  MeasurementsFile other{"fake", "smoke", "abc", {}};
  other.m.scalar("a.scalar", 1);
  other.m.trend("a.trend", true, "");
  other.m.curve("a.curve", {{0, 1}, {0, 1}});
  EXPECT_FALSE(make_baseline(short_curve, {other}, RebaselineRule{}, "t", "n").find("a.curve")->gated);
  MeasurementsFile missing{"fake", "smoke", "abc", {}};
  EXPECT_THROW(make_baseline(short_curve, {missing}, RebaselineRule{}, "t", "n"), std::runtime_error);
}

TEST(Gate, EveryVerdict) {
  const Baseline b = baseline_of(1e-12);
  auto verdict = [&](const MeasurementsFile& f, const std::string& id) {
    for (const auto& r : compare_to_baseline(b, f.m))
      if (r.id == id) return r.verdict;
    return Verdict::same;
  };
  EXPECT_EQ(verdict(run(10.0, true, {0, 1, 2}), "a.scalar"), Verdict::same);
  EXPECT_EQ(verdict(run(10.0 + 2e-12, true, {0, 1, 2}), "a.scalar"), Verdict::within);
  EXPECT_EQ(verdict(run(10.0 + 1e-10, true, {0, 1, 2}), "a.scalar"), Verdict::moved);
  EXPECT_EQ(verdict(run(NAN, true, {0, 1, 2}), "a.scalar"), Verdict::moved);
  EXPECT_EQ(verdict(run(10.0, false, {0, 1, 2}), "a.trend"), Verdict::moved);
  EXPECT_EQ(verdict(run(10.0, true, {0, 1, 2 + 1e-9}), "a.curve"), Verdict::moved);
  EXPECT_EQ(verdict(run(10.0, true, {0, 1, 2 + 1e-12}), "a.curve"), Verdict::within);
  MeasurementsFile fewer{"fake", "smoke", "abc", {}};
  fewer.m.scalar("a.scalar", 10.0);
  fewer.m.scalar("a.new", 1.0);
  const auto rows = compare_to_baseline(b, fewer.m);  // baseline order (ids sorted), new ids last
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].id, "a.curve");
  EXPECT_EQ(rows[0].verdict, Verdict::missing);
  EXPECT_EQ(rows[2].verdict, Verdict::missing);
  EXPECT_EQ(rows[3].id, "a.new");
  EXPECT_EQ(rows[3].verdict, Verdict::added);
  EXPECT_TRUE(rows[3].fails());
  EXPECT_EQ(rows[3].now, "1");  // a new id shows the value a rebaseline would record
  // A moved row's table names the value, both numbers and why the tolerance is what it is.
  const auto moved = compare_to_baseline(b, run(11.0, true, {0, 1, 2}).m);
  const std::string table = gate_table_text({moved[1]});
  for (const char* part : {"a.scalar", "10", "11", "MOVED", "largest change"})
    EXPECT_NE(table.find(part), std::string::npos) << part << "\n" << table;
}

TEST(Gate, FilesRoundTripAndTheReaderIsStrict) {
  kolsky::testing::TempDir dir("kolsky_test_gate");
  MeasurementsFile f = run(NAN, true, {0, 1, 2});
  write_measurements(dir.str(), "fake", "smoke", f.m);
  const MeasurementsFile back = read_measurements(dir.file("measurements.json"));
  EXPECT_TRUE(std::isnan(back.m.find("a.scalar")->value));
  EXPECT_EQ(back.m.find("a.curve")->curve.y, (std::vector<double>{0, 1, 2}));

  const Baseline b = baseline_of(1e-12);
  {
    std::ofstream(dir.file("b.json")) << baseline_json(b).dump(1);
  }
  const Baseline again = load_baseline(dir.file("b.json"));
  EXPECT_EQ(baseline_digest(again), baseline_digest(b));
  nlohmann::json j = baseline_json(b);
  j["values"][0]["tolerance"] = 1;
  {
    std::ofstream(dir.file("bad.json")) << j.dump();
  }
  try {
    load_baseline(dir.file("bad.json"));
    FAIL() << "unknown key accepted";
  } catch (const kolsky::InputError& e) {
    EXPECT_EQ(e.path(), "values[0].tolerance");
  }
  // The digest follows the values: an edited value has a new digest, missing from the log.
  Baseline edited = b;
  edited.values[1].value += 1;  // a.scalar
  EXPECT_NE(baseline_digest(edited), baseline_digest(b));
  const std::string log = "# Baseline log\n\n## 2026 · fake · smoke · commit x · digest " +
                          baseline_digest(b) + "\n\nReason: r\n";
  EXPECT_TRUE(log_has_entry(log, b));
  EXPECT_FALSE(log_has_entry(log, edited));
  Baseline other_set = b;
  other_set.set = "other";
  EXPECT_FALSE(log_has_entry(log, other_set));
}

TEST(Gate, CommandLineFailsWithATableAndPassesAfterRebaseline) {
  kolsky::testing::TempDir dir("kolsky_test_gate_cli");
  const fs::path repo = dir.str();
  fs::create_directories(repo / "reproductions/fake");
  std::ofstream(repo / "reproductions/fake/driver.cpp") << "// a set\n";
  const std::string gate = std::string(KOLSKY_BINARY_DIR) + "/reproductions/kolsky_gate";
  auto sh = [&](const std::string& args) {
    const std::string cmd = gate + " " + args + " --repo " + repo.string() + " > " + dir.file("out.txt") + " 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  // No baseline yet: fails and says how to make one.
  write_measurements((repo / "results/fake").string(), "fake", "smoke", run(10, true, {0, 1, 2}).m);
  EXPECT_EQ(sh("check --results " + (repo / "results").string()), 1);
  EXPECT_NE(read_text(dir.file("out.txt")).find("make rebaseline SET=fake"), std::string::npos);
  // Rebaseline from one run and a perturbed one, then the same values pass.
  write_measurements((repo / "p1/fake").string(), "fake", "smoke", run(10 + 1e-12, true, {0, 1, 2}).m);
  EXPECT_EQ(sh("rebaseline --set fake --scale smoke --runs " + (repo / "results/fake").string() + " " +
               (repo / "p1/fake").string() + " --reason 'first'"), 0);
  EXPECT_NE(read_text((repo / "reproductions/BASELINES.md").string()).find("Reason: first"), std::string::npos);
  EXPECT_EQ(sh("check --results " + (repo / "results").string()), 0);
  // A moved value fails with its row.
  write_measurements((repo / "results/fake").string(), "fake", "smoke", run(10.5, true, {0, 1, 2}).m);
  EXPECT_EQ(sh("check --results " + (repo / "results").string()), 1);
  const std::string out = read_text(dir.file("out.txt"));
  EXPECT_NE(out.find("a.scalar"), std::string::npos) << out;
  EXPECT_NE(out.find("MOVED"), std::string::npos) << out;
  // A baseline changed by hand (no log entry for its digest) fails too.
  write_measurements((repo / "results/fake").string(), "fake", "smoke", run(10, true, {0, 1, 2}).m);
  nlohmann::json b = nlohmann::json::parse(read_text((repo / "reproductions/fake/baseline_smoke.json").string()));
  b["values"][0]["why"] = "edited";
  std::ofstream(repo / "reproductions/fake/baseline_smoke.json") << b.dump();
  EXPECT_EQ(sh("check --results " + (repo / "results").string()), 1);
  EXPECT_NE(read_text(dir.file("out.txt")).find("has no entry"), std::string::npos);
  // Bad input: exit 2 naming the file.
  std::ofstream(repo / "reproductions/fake/baseline_smoke.json") << "{";
  EXPECT_EQ(sh("check --results " + (repo / "results").string()), 2);
  EXPECT_NE(read_text(dir.file("out.txt")).find("baseline_smoke.json"), std::string::npos);
}
