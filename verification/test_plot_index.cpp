// The reports index (harness/index.hpp) over a reports folder made by hand: counts as
// report.md counts them, run time and commit from results.json, links to each report, the
// plots inline with their titles, a set that did not run listed as such, and no scripts in the
// HTML.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "harness/index.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using namespace kolsky::harness;

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

void write_results(const fs::path& dir, const std::string& targets) {
  fs::create_directories(dir / "plots_src");
  std::ofstream(dir / "results.json")
      << R"({"set": ")" << dir.filename().string()
      << R"(", "scale": "full", "git_commit": "abc123", "wall_time_s": 125.0, "targets": [)"
      << targets << "]}";
}

TEST(ReportsIndex, CountsLinksAndPlotsOfEverySet) {
  kolsky::testing::TempDir dir("kolsky_test_index");
  const fs::path reports = dir.str();
  const std::string pass = R"({"id": "a", "status": "expected_pass", "pass": true})";
  const std::string fail = R"({"id": "b", "status": "expected_pass", "pass": false})";
  const std::string known = R"({"id": "c", "status": "known_deviation", "pass": false})";
  const std::string surprise = R"({"id": "d", "status": "known_deviation", "pass": true, "unexpected_pass": true})";
  write_results(reports / "bars", pass + "," + pass + "," + known);
  write_results(reports / "chapter2", pass + "," + fail + "," + known + "," + surprise);
  std::ofstream(reports / "bars" / "waves.png") << "png";
  std::ofstream(reports / "bars" / "plots_src" / "waves.gp") << "# Face <waves>\nplot x\n";
  write_results(reports / "extra", pass);  // not named: found, listed after the named ones

  EXPECT_EQ(write_index(reports.string(), {"bars", "chapter2", "chapter3"}), 1);  // chapter2 fails
  const auto rows = read_index(reports.string(), {"bars", "chapter2", "chapter3"});
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].n_pass, 2);
  EXPECT_EQ(rows[0].n_known, 1);
  EXPECT_EQ(rows[1].n_fail, 1);
  EXPECT_EQ(rows[1].n_unexpected, 1);
  EXPECT_FALSE(rows[2].has_report);
  EXPECT_EQ(rows[3].set, "extra");
  EXPECT_EQ(rows[0].captions, std::vector<std::string>{"Face <waves>"});

  const std::string md = slurp((reports / "index.md").string());
  EXPECT_NE(md.find("| bars | <span style=\"color:green\">**PASS**</span> | 2 | 0 | 1 | 0 | full | 125 s (2.1 min) | abc123 |"),
            std::string::npos) << md;
  EXPECT_NE(md.find("[report](chapter2/report.md)"), std::string::npos);
  EXPECT_NE(md.find("| chapter3 | no report (not run) |"), std::string::npos);
  EXPECT_NE(md.find("![Face <waves>](bars/waves.png)"), std::string::npos);

  const std::string html = slurp((reports / "index.html").string());
  EXPECT_NE(html.find("<td class=\"FAIL\">FAIL</td>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"bars/results.json\">results</a>"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"bars/waves.png\" alt=\"Face &lt;waves&gt;\">"), std::string::npos) << html;
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

TEST(ReportsIndex, BrokenResultsNamesTheFile) {
  kolsky::testing::TempDir dir("kolsky_test_index");
  fs::create_directories(fs::path(dir.str()) / "bars");
  std::ofstream(fs::path(dir.str()) / "bars" / "results.json") << "{\"targets\": 3";
  try {
    write_index(dir.str(), {"bars"});
    FAIL() << "no error";
  } catch (const kolsky::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bars/results.json"), std::string::npos) << e.what();
  }
}

}  // namespace
