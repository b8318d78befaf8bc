// `kolsky analyze|run --plot DIR` end to end (the program at its absolute build path), and the
// figures of a simulated run chosen from its probes: every PNG is written, non-empty and a PNG
// by signature; a missing gnuplot (KOLSKY_GNUPLOT at a path that does not exist) or an unusable
// DIR stops the command with exit 2, naming --plot, before any output is written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "plot/gnuplot.hpp"
#include "plot/shpb_figures.hpp"
#include "shpb/probe_record.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using kolsky::testing::TempDir;

const std::string kRepo = KOLSKY_SOURCE_DIR;
const std::string kKolsky = std::string(KOLSKY_BINARY_DIR) + "/kolsky";

std::string read_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

/// Runs the program with `env` (e.g. "KOLSKY_GNUPLOT=/x") in front; stdout+stderr to log.
int kolsky(const std::string& env, const std::string& args, const std::string& log) {
  const std::string cmd = env + " " + kKolsky + " " + args + " > " + log + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void expect_png(const std::string& path) {
  ASSERT_TRUE(fs::exists(path)) << path;
  EXPECT_GT(fs::file_size(path), 1000u) << path;
  EXPECT_EQ(read_text(path).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << path;
}

bool have_gnuplot() { return kolsky::plot::gnuplot_missing(kolsky::plot::default_gnuplot()).empty(); }

/// The CLI tests' small elastic scene: 2 m and 1 m bars with one gauge each, 0.6 ms.
std::string smoke_scene(const TempDir& dir) {
  const std::string path = dir.file("smoke.json");
  std::ofstream(path) << R"({"bars": {"incident": {"length": 2.0, "gauges": [1.0]},
    "transmission": {"length": 1.0, "gauges": [0.5]}},
    "pulse": {"kind": "trapezoid", "amplitude": 50e6, "rise_time": 20e-6, "duration": 100e-6,
              "fall_time": 20e-6},
    "specimen": {"model": "elastic", "constrained_modulus": 230e6, "n_elements": 10},
    "time": {"end": 0.6e-3}})";
  return path;
}

const char* kAnalysisPngs[] = {"waves.png", "strain_rate.png", "stress_strain.png", "alpha.png",
                               "energies.png", "gauges.png"};

TEST(PlotCli, AnalyzeExampleRecordWritesPngs) {
  if (!have_gnuplot()) GTEST_SKIP() << "no gnuplot (scripts/install-deps.sh installs it)";
  TempDir dir("kolsky_test_plot");
  const std::string args = kRepo + "/data/examples/gauges_song2009_example.csv --bars " + kRepo +
                           "/data/examples/bars_song2009.json -o " + dir.file("a.csv") +
                           " --quiet --plot " + dir.file("figs");
  ASSERT_EQ(kolsky("", "analyze " + args, dir.file("log.txt")), 0) << read_text(dir.file("log.txt"));
  for (const char* png : kAnalysisPngs) expect_png(dir.file("figs/") + png);
  EXPECT_TRUE(fs::exists(dir.file("figs/plots_src/gauges.gp")));  // kept for re-running
  // The input file is in every title, the windows and offsets on the raw records.
  const std::string gp = read_text(dir.file("figs/plots_src/gauges.gp"));
  EXPECT_NE(gp.find("gauges_song2009_example.csv"), std::string::npos);
  EXPECT_NE(gp.find("reflected window"), std::string::npos);
  EXPECT_NE(gp.find("removed offset, incident"), std::string::npos);
  EXPECT_NE(read_text(dir.file("figs/plots_src/alpha.gp")).find("0.05 (equilibrium)"), std::string::npos);
}

TEST(PlotCli, RunSmokeSceneWritesPngs) {
  if (!have_gnuplot()) GTEST_SKIP() << "no gnuplot (scripts/install-deps.sh installs it)";
  TempDir dir("kolsky_test_plot");
  const std::string scene = smoke_scene(dir);
  const std::string args = "run " + scene + " -o " + dir.file("s.h5") + " --quiet --plot " + dir.file("figs");
  ASSERT_EQ(kolsky("", args, dir.file("log.txt")), 0) << read_text(dir.file("log.txt"));
  for (const char* png : kAnalysisPngs) expect_png(dir.file("figs/") + png);
  // The probes the analysis figures do not show get a figure each.
  expect_png(dir.file("figs/probe_face_rate_front.png"));
  expect_png(dir.file("figs/probe_energy_held.png"));
  EXPECT_FALSE(fs::exists(dir.file("figs/probe_wave_incident.png")));  // it is waves.png
}

TEST(PlotCli, MissingGnuplotStopsBeforeAnyWork) {
  TempDir dir("kolsky_test_plot");
  const std::string missing = "KOLSKY_GNUPLOT=" + dir.file("no_such_gnuplot");
  const std::string analyze = "analyze " + kRepo + "/data/examples/gauges_song2009_example.csv --bars " +
                              kRepo + "/data/examples/bars_song2009.json -o " + dir.file("a.csv") +
                              " --plot " + dir.file("figs");
  EXPECT_EQ(kolsky(missing, analyze, dir.file("log.txt")), 2);
  std::string log = read_text(dir.file("log.txt"));
  EXPECT_NE(log.find("--plot: gnuplot not available at " + dir.file("no_such_gnuplot")), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir.file("a.csv")));
  EXPECT_FALSE(fs::exists(dir.file("figs")));

  const std::string run = "run " + smoke_scene(dir) + " -o " + dir.file("s.h5") + " --plot " + dir.file("figs");
  EXPECT_EQ(kolsky(missing, run, dir.file("log.txt")), 2);
  log = read_text(dir.file("log.txt"));
  EXPECT_NE(log.find("--plot: gnuplot not available"), std::string::npos) << log;
  EXPECT_EQ(log.find("steps of"), std::string::npos) << "the run started: " << log;
  EXPECT_FALSE(fs::exists(dir.file("s.h5")));
  EXPECT_EQ(kolsky("KOLSKY_GNUPLOT=", run, dir.file("log.txt")), 2);  // empty: plotting off
}

TEST(PlotCli, UnusablePlotFolderIsBadInput) {
  if (!have_gnuplot()) GTEST_SKIP() << "no gnuplot";
  TempDir dir("kolsky_test_plot");
  std::ofstream(dir.file("a_file")) << "x";
  const std::string run = "run " + smoke_scene(dir) + " -o " + dir.file("s.h5") + " --plot " + dir.file("a_file");
  EXPECT_EQ(kolsky("", run, dir.file("log.txt")), 2);
  EXPECT_NE(read_text(dir.file("log.txt")).find("--plot: cannot create or write the folder"), std::string::npos)
      << read_text(dir.file("log.txt"));
  EXPECT_FALSE(fs::exists(dir.file("s.h5")));
}

TEST(PlotFigures, RunFiguresDrawModelProbesOnce) {
  // A DEM run's probes, synthetic: the figures follow the names, not the model.
  kolsky::shpb::RunResult r;
  r.t = {0, 1e-6, 2e-6};
  const std::vector<double> v = {0, 1, 2};
  for (const std::string& name : {kolsky::shpb::gauge_probe_name("incident", 0),
                                 kolsky::shpb::gauge_probe_name("incident", 1),
                                 kolsky::shpb::gauge_probe_name("transmission", 0),
                                 std::string("wave_incident"), std::string("coordination_number"),
                                 std::string("grain_kinetic_energy")})
    r.probes.push_back({name, name == "grain_kinetic_energy" ? "J" : "1", "what " + name, v});
  r.probes.push_back({"never_finite", "1", "", std::vector<double>(3, std::nan(""))});
  const auto figs = kolsky::plot::run_figures(r, {}, {}, "scene.json");
  std::vector<std::string> files;
  for (const auto& f : figs) files.push_back(f.file);
  EXPECT_EQ(files, (std::vector<std::string>{"gauges.png", "probe_coordination_number.png",
                                             "probe_grain_kinetic_energy.png"}));
  EXPECT_EQ(figs[0].series.size(), 3u);  // every gauge of both bars
  EXPECT_EQ(figs[2].ylabel, "grain_kinetic_energy (J)");
  EXPECT_NE(figs[1].title.find("scene.json"), std::string::npos);
}

}  // namespace
