// The two uses of the results: the summary (figures and README of reports/benchmarks/) and
// bench-check (this run's ratios against the newest tracked ones).
#pragma once
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "summary/results.hpp"

namespace kolsky::benchsum {

/// Writes out_dir/{dem_compaction,fe_elem_updates,dem_upscaling}.png (when there is data and
/// gnuplot) and out_dir/README.md; says on `log` what it wrote. Returns the paths written.
std::vector<std::string> write_summary(const std::vector<ResultFile>& files,
                                       const std::vector<std::string>& skipped,
                                       const std::string& out_dir, const std::string& gnuplot,
                                       std::ostream& log);

/// One tracked figure of bench-check.
struct CheckRow {
  Tracked figure;
  std::optional<Ratio> now, base;
  std::string base_file, base_date;
  double margin = 0;  ///< allowed relative drop below the tracked ratio
  bool regression = false;
  std::string skipped;  ///< why this run's ratio is not compared (second core busy), or ""
};

/// For every tracked figure that a run file has: the newest tracked file (by date) of the same
/// bench whose reference has the run's reference version and whose kernel ran on the same
/// input (label), and whether the run's ratio fell
/// more than its margin below that one. Throws std::invalid_argument when a margin is missing.
std::vector<CheckRow> compare(const std::vector<ResultFile>& tracked_files, const std::vector<ResultFile>& runs,
                              const std::map<std::string, double>& margins);

/// The readable table of compare()'s rows, with the rates behind each ratio.
std::string format_check(const std::vector<CheckRow>& rows);

/// The spread of each tracked ratio (and of its kernel and reference rates) over several runs:
/// each value, median, min, max, and the largest drop below the median.
std::string format_spread(const std::vector<ResultFile>& runs);

/// printf-formatted number (one format, one value), for tables.
std::string fmt(const char* format, double v);

}  // namespace kolsky::benchsum
