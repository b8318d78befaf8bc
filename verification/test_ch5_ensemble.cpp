// The Chapter 5 set as an ensemble (reproductions/chapter5/set.hpp, case_json.hpp): a case's
// record and a back-calculation's result read back from JSON bit for bit (NaN of either sign,
// infinities, -0, subnormals), results handed to their places in member order whatever the
// schedule, a member that throws logged with its error while the others go on, the members log
// read back as costs, and the phase-by-phase list-scheduling model. The set's runs themselves
// are the chapter5 smoke set (its values held by the regression gate; under mpirun -n 2 by
// CTest reproduce_chapter5_mpi_2).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <utility>

#include "chapter5/case_json.hpp"
#include "chapter5/set.hpp"

namespace kolsky::ch5 {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_bits(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(same_bits(a[k], b[k])) << what << "[" << k << "]";
}

const std::vector<double> kAwkward = {0.1, -0.0, 1.0 / 3.0, 5e-324, 1.7976931348623157e308, -2.5e-310,
                                      std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN(),
                                      INFINITY, -INFINITY, 72e6, 1.33e-9};

CaseResult awkward_case() {
  CaseResult c;
  c.spec.label = "Wang N = 1.5 (seed 2)";
  c.spec.scene = "scene_wang.json";
  c.spec.upscale = 1.5;
  c.spec.sigma_lim0 = 2.2467e9;
  c.spec.breakage = false;
  c.spec.seed = 2;
  c.spec.sets = {"specimen.grain_size_curve=\"x.csv\""};
  c.ok = true;
  c.upscale = 1.5, c.wall_s = 12.3, c.pack_s = 0.4, c.dt = 2.43e-9, c.simulated_s = 1.5e-4, c.dt_final = 2.43e-9;
  c.steps = 61607;
  c.grains_initial = 12940, c.grains_final = 25485;
  c.t = c.strain = c.stress_back = c.stress_avg = kAwkward;
  c.grain_count = c.broken_primary = c.broken_secondary = c.relative_breakage = kAwkward;
  c.curves = {{1e-6, {{1e-4, 2e-4}, {10.0 / 3.0, 100}}}, {-0.0, {{}, {}}}};
  c.gauges = {kAwkward, kAwkward, kAwkward};
  c.coordination_final = -std::numeric_limits<double>::quiet_NaN();
  c.ended_by = "back-wall stress reached";
  return c;
}

void expect_same_case(const CaseResult& a, const CaseResult& b) {
  EXPECT_EQ(to_json(a.spec), to_json(b.spec));
  EXPECT_EQ(a.ok, b.ok);
  EXPECT_EQ(a.failure, b.failure);
  for (auto [x, y] : std::initializer_list<std::pair<double, double>>{{a.upscale, b.upscale}, {a.wall_s, b.wall_s}, {a.pack_s, b.pack_s}, {a.dt, b.dt},
                      {a.simulated_s, b.simulated_s}, {a.dt_final, b.dt_final}, {a.arrival_time, b.arrival_time},
                      {a.coordination_final, b.coordination_final}})
    EXPECT_TRUE(same_bits(x, y)) << x << " " << y;
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.grains_initial, b.grains_initial);
  EXPECT_EQ(a.grains_final, b.grains_final);
  expect_same_bits(a.t, b.t, "t");
  expect_same_bits(a.stress_avg, b.stress_avg, "stress_avg");
  expect_same_bits(a.relative_breakage, b.relative_breakage, "relative_breakage");
  expect_same_bits(a.gauges.transmission, b.gauges.transmission, "gauges");
  ASSERT_EQ(a.curves.size(), b.curves.size());
  for (std::size_t k = 0; k < a.curves.size(); ++k) {
    EXPECT_TRUE(same_bits(a.curves[k].t, b.curves[k].t));
    expect_same_bits(a.curves[k].curve.percent_passing, b.curves[k].curve.percent_passing, "curve");
  }
  EXPECT_EQ(a.ended_by, b.ended_by);
}

TEST(Chapter5Ensemble, ACaseReadsBackBitForBitThroughJsonText) {
  const CaseResult c = awkward_case();
  // As the executors carry it: dumped to text (cache file, MPI message) and parsed again.
  const CaseResult back = case_from_json(nlohmann::json::parse(to_json(c).dump()));
  expect_same_case(c, back);
  EXPECT_EQ(back.spec.sets, c.spec.sets);
  EXPECT_FALSE(back.spec.breakage);
}

TEST(Chapter5Ensemble, ABackCalculationReadsBackWithItsFailedRuns) {
  BackCalcResult r;
  r.sigma = 2.247e9, r.score = 3.16e6, r.bracket_lo = 2.107e9, r.bracket_hi = 2.295e9, r.converged = true;
  r.evaluated = {{2.295e9, 4.1e6}, {1.836e9, INFINITY}, {2.247e9, 3.16e6}};  // a failed run scores +inf
  r.best = awkward_case();
  r.note = "converged";
  const BackCalcResult back = backcalc_from_json(nlohmann::json::parse(to_json(r).dump()));
  EXPECT_TRUE(same_bits(back.sigma, r.sigma));
  EXPECT_EQ(back.evaluated, r.evaluated);
  EXPECT_TRUE(back.converged);
  EXPECT_EQ(back.note, r.note);
  expect_same_case(r.best, back.best);
}

// Members of uneven expected cost on two threads: each result lands where its member asked,
// in member order, and one that throws is logged with its error while the rest go on.
TEST(Chapter5Ensemble, ResultsGoToTheirPlacesInMemberOrder) {
  SetEnsemble e;
  e.options.threads = 2;
  const CaseRunner r{"/nonexistent", "/tmp", 0};
  CaseSpec spec;
  spec.label = "no scene";
  spec.scene = "missing.json";
  std::vector<double> got(5, -1);
  nlohmann::json thrown = "untouched";
  for (int k = 0; k < 5; ++k) {
    spec.label = "member " + std::to_string(k);
    add_chain(e, r, spec.label, spec, "", 1.0 + (k % 3), [k] { return nlohmann::json(k * 1.5); },
              [&got, k](const nlohmann::json& j) { got[k] = j.get<double>(); });
  }
  add_chain(e, r, "thrower", spec, "", 9, []() -> nlohmann::json { throw std::runtime_error("blew up"); },
            [&thrown](const nlohmann::json& j) { thrown = j; });
  CaseResult failed;
  spec.label = "unreadable case";
  add_case(e, r, spec, &failed);
  run_phase(e, "A");
  for (int k = 0; k < 5; ++k) EXPECT_EQ(got[k], k * 1.5);
  EXPECT_TRUE(thrown.is_null());
  EXPECT_FALSE(failed.ok);  // run_case's own failure: the scene file is not there
  EXPECT_NE(failed.failure.find("missing.json"), std::string::npos) << failed.failure;
  ASSERT_EQ(e.log.size(), 7u);
  EXPECT_EQ(e.log[5].label, "thrower");
  EXPECT_FALSE(e.log[5].ok);
  EXPECT_EQ(e.log[5].error, "blew up");
  EXPECT_TRUE(e.log[6].ok);
  EXPECT_TRUE(e.members.empty());  // ready for the next phase
}

TEST(Chapter5Ensemble, TheScheduleModelRunsPhaseByPhase) {
  std::vector<MemberRecord> log;
  for (double w : {10.0, 5.0, 5.0}) log.push_back({"A", "a", 1, false, w, 0, true, false, ""});
  for (double w : {8.0, 2.0}) log.push_back({"B", "b", 1, false, w, 0, true, false, ""});
  const SetSchedule s = model_schedule(log, 2);
  EXPECT_DOUBLE_EQ(s.makespan, 10 + 8);       // A: 10 | 5 + 5; B: 8 | 2
  EXPECT_DOUBLE_EQ(s.critical_path, 10 + 8);  // the longest member of each phase
  EXPECT_DOUBLE_EQ(s.idle_fraction, 1 - 30.0 / (2 * 18));
  EXPECT_DOUBLE_EQ(model_schedule(log, 64).makespan, 18);
  EXPECT_NE(members_markdown(log, "2 thread(s)").find("| 64 | 18 s | 18 s |"), std::string::npos);
}

TEST(Chapter5Ensemble, TheMembersLogReadsBackAsMeasuredCosts) {
  std::vector<MemberRecord> log = {{"A", "Wang N = 2.5", 700, false, 41.5, 1, true, false, ""},
                                   {"A", "cached", 700, false, 0, 0, true, true, ""},
                                   {"B", "failed", 700, false, 3, 0, false, false, "x"}};
  const auto back = members_from_json(nlohmann::json::parse(members_json(log).dump()));
  ASSERT_EQ(back.size(), 3u);
  EXPECT_EQ(back[0].label, "Wang N = 2.5");
  EXPECT_EQ(back[0].wall_s, 41.5);
  EXPECT_EQ(back[2].error, "x");
  const std::string path = std::string(KOLSKY_BINARY_DIR) + "/test_ch5_members.json";
  std::ofstream(path) << members_json(log).dump();
  const CostTable t = read_costs(path);
  ASSERT_EQ(t.measured.size(), 1u);  // neither a cached nor a failed member's time is a cost
  EXPECT_EQ(t.measured.at("Wang N = 2.5"), 41.5);
  std::filesystem::remove(path);
  EXPECT_TRUE(read_costs(path).measured.empty());
}

}  // namespace
}  // namespace kolsky::ch5
