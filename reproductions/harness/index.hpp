// One page over every reproduction set, written at the end of `make reproduce`:
// <reports>/index.md and a static <reports>/index.html (same tables, the sets' plots inline as
// <img>, no scripts). Per set: result, pass / fail / known-deviation / unexpected-pass counts,
// scale, run time, commit and links to report.md, results.json and measurements.json, all read
// from <reports>/<set>/results.json as write_report leaves it (report.hpp). A set without one
// is listed as "no report". Plot captions come from the first line of plots_src/<plot>.gp.
#pragma once
#include <string>
#include <vector>

namespace kolsky::harness {

/// One set's line of the index.
struct IndexRow {
  std::string set;
  bool has_report = false;
  std::string scale, commit;
  double wall_time_s = 0;
  int n_pass = 0, n_fail = 0, n_known = 0, n_unexpected = 0;
  std::vector<std::string> plots;     ///< PNG file names in <reports>/<set>/, sorted
  std::vector<std::string> captions;  ///< one per plot (its title, else its file name)
};

/// Rows for `sets` (in that order) and for every other <reports>/<dir>/results.json (sorted).
/// Throws kolsky::InputError naming the file for a results.json that is not one.
std::vector<IndexRow> read_index(const std::string& reports_dir, const std::vector<std::string>& sets);

std::string index_markdown(const std::vector<IndexRow>& rows);
std::string index_html(const std::vector<IndexRow>& rows);

/// read_index, then writes index.md and index.html into reports_dir (atomically).
/// Returns the number of sets with a report that fails (expected_pass targets failing).
int write_index(const std::string& reports_dir, const std::vector<std::string>& sets);

}  // namespace kolsky::harness
