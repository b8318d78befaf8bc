// The reports index (see index.hpp). Counting follows report.md's "Result" line: an
// expected_pass target passes or fails the set; a known deviation never fails it and is counted
// apart when it unexpectedly passes.
#include "harness/index.hpp"

#include "core/atomic_file.hpp"
#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "io/xml_escape.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace kolsky::harness {
namespace {

namespace fs = std::filesystem;

IndexRow read_row(const fs::path& dir, const std::string& set) {
  IndexRow row;
  row.set = set;
  const fs::path file = dir / "results.json";
  if (!fs::exists(file)) return row;
  std::ifstream in(file);
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    row.scale = j.value("scale", "");
    row.commit = j.value("git_commit", "");
    row.wall_time_s = j["wall_time_s"].is_number() ? j["wall_time_s"].get<double>() : 0.0;
    for (const auto& t : j.at("targets")) {
      const bool pass = t.at("pass").get<bool>();
      if (t.at("status").get<std::string>() == "expected_pass") (pass ? row.n_pass : row.n_fail)++;
      else (t.value("unexpected_pass", false) ? row.n_unexpected : row.n_known)++;
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string(), "", std::string("not a results.json: ") + e.what());
  }
  row.has_report = true;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".png") row.plots.push_back(e.path().filename());
  std::sort(row.plots.begin(), row.plots.end());
  for (const std::string& png : row.plots) {
    // render_plot's script starts with "# <title>".
    std::ifstream gp(dir / "plots_src" / (fs::path(png).stem().string() + ".gp"));
    std::string first;
    std::getline(gp, first);
    row.captions.push_back(first.size() > 2 && first[0] == '#' ? first.substr(2) : png);
  }
  return row;
}

std::string fmt_time(double s) {
  char buf[48];
  if (s >= 60) std::snprintf(buf, sizeof buf, "%.0f s (%.1f min)", s, s / 60);
  else std::snprintf(buf, sizeof buf, "%.3g s", s);
  return buf;
}

/// The cells of one row, as text; `link` makes a link from (label, target).
template <class Link>
std::vector<std::string> cells(const IndexRow& r, Link link) {
  if (!r.has_report) return {r.set, "no report (not run)", "-", "-", "-", "-", "-", "-", "-", "-"};
  return {r.set,
          r.n_fail == 0 ? "PASS" : "FAIL",
          std::to_string(r.n_pass),
          std::to_string(r.n_fail),
          std::to_string(r.n_known),
          std::to_string(r.n_unexpected),
          r.scale,
          fmt_time(r.wall_time_s),
          r.commit,
          link("report", r.set + "/report.md") + ", " + link("results", r.set + "/results.json") +
              ", " + link("measurements", r.set + "/measurements.json")};
}

const std::vector<std::string> kHeader = {"set",   "result",   "passed", "failed", "known deviations",
                                          "unexpected passes", "scale", "run time", "commit", "files"};

constexpr const char* kIntro =
    "Each reproduction set, scored against its targets (docs/reproductions.md). Known "
    "deviations never fail a set; an unexpected pass is a known deviation that now passes "
    "(remove its note in targets.json).";  // plain text: it goes into the HTML as well

}  // namespace

std::vector<IndexRow> read_index(const std::string& reports_dir, const std::vector<std::string>& sets) {
  std::vector<IndexRow> rows;
  for (const std::string& s : sets) rows.push_back(read_row(fs::path(reports_dir) / s, s));
  std::vector<std::string> others;
  if (fs::is_directory(reports_dir))
    for (const auto& e : fs::directory_iterator(reports_dir)) {
      const std::string name = e.path().filename();
      if (fs::exists(e.path() / "results.json") && std::find(sets.begin(), sets.end(), name) == sets.end())
        others.push_back(name);
    }
  std::sort(others.begin(), others.end());
  for (const std::string& s : others) rows.push_back(read_row(fs::path(reports_dir) / s, s));
  return rows;
}

std::string index_markdown(const std::vector<IndexRow>& rows) {
  std::string md = "# Reproduction reports\n\n" + std::string(kIntro) + "\n\n|";
  std::string rule = "|";
  for (const std::string& h : kHeader) md += " " + h + " |", rule += "---|";
  md += "\n" + rule + "\n";
  const auto link = [](const std::string& label, const std::string& to) { return "[" + label + "](" + to + ")"; };
  for (const IndexRow& r : rows) {
    std::vector<std::string> c = cells(r, link);
    if (r.has_report)  // in colour, as in report.md
      c[1] = "<span style=\"color:" + std::string(r.n_fail == 0 ? "green" : "red") + "\">**" + c[1] + "**</span>";
    md += "|";
    for (const std::string& x : c) md += " " + x + " |";
    md += "\n";
  }
  for (const IndexRow& r : rows) {
    if (r.plots.empty()) continue;
    md += "\n## " + r.set + "\n\n";
    for (size_t i = 0; i < r.plots.size(); ++i)
      md += "![" + r.captions[i] + "](" + r.set + "/" + r.plots[i] + ")\n\n";
  }
  return md + "\n*Index written by kolsky " + build_info::git_commit() + ".*\n";
}

std::string index_html(const std::vector<IndexRow>& rows) {
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>kolsky reproduction reports</title>\n<style>\n"
      "body{font-family:sans-serif;margin:2em;max-width:1100px}\n"
      "table{border-collapse:collapse}td,th{border:1px solid #999;padding:4px 8px}\n"
      ".PASS{color:green;font-weight:bold}.FAIL{color:red;font-weight:bold}\n"
      "img{max-width:100%;border:1px solid #ddd}figure{margin:1em 0}\n"
      "</style>\n</head>\n<body>\n<h1>Reproduction reports</h1>\n<p>" +
      io::xml_escape(kIntro) + "</p>\n<table>\n<tr>";
  for (const std::string& c : kHeader) h += "<th>" + io::xml_escape(c) + "</th>";
  h += "</tr>\n";
  const auto link = [](const std::string& label, const std::string& to) {
    return "<a href=\"" + io::xml_escape(to) + "\">" + io::xml_escape(label) + "</a>";
  };
  for (const IndexRow& r : rows) {
    const std::vector<std::string> c = cells(r, link);
    h += "<tr>";
    for (size_t i = 0; i < c.size(); ++i) {
      const bool is_result = i == 1 && r.has_report;
      const bool is_links = i + 1 == c.size() && r.has_report;  // already HTML
      h += (is_result ? "<td class=\"" + c[i] + "\">" : std::string("<td>")) +
           (is_links ? c[i] : io::xml_escape(c[i])) + "</td>";
    }
    h += "</tr>\n";
  }
  h += "</table>\n";
  for (const IndexRow& r : rows) {
    if (r.plots.empty()) continue;
    h += "<h2>" + io::xml_escape(r.set) + "</h2>\n";
    for (size_t i = 0; i < r.plots.size(); ++i)
      h += "<figure><img src=\"" + io::xml_escape(r.set + "/" + r.plots[i]) + "\" alt=\"" +
           io::xml_escape(r.captions[i]) + "\"><figcaption>" + io::xml_escape(r.captions[i]) +
           "</figcaption></figure>\n";
  }
  return h + "<p><em>Index written by kolsky " + io::xml_escape(build_info::git_commit()) +
         ".</em></p>\n</body>\n</html>\n";
}

int write_index(const std::string& reports_dir, const std::vector<std::string>& sets) {
  const std::vector<IndexRow> rows = read_index(reports_dir, sets);
  fs::create_directories(reports_dir);
  write_file_atomic((fs::path(reports_dir) / "index.md").string(), index_markdown(rows));
  write_file_atomic((fs::path(reports_dir) / "index.html").string(), index_html(rows));
  return static_cast<int>(std::count_if(rows.begin(), rows.end(),
                                        [](const IndexRow& r) { return r.has_report && r.n_fail > 0; }));
}

}  // namespace kolsky::harness
