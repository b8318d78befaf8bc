// The kolsky subcommands and their shared option parsing.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace kolsky::app {

/// Wrong command-line usage (exit code 1).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int cmd_run(const std::vector<std::string>& args);
int cmd_analyze(const std::vector<std::string>& args);
int cmd_defaults(const std::vector<std::string>& args);
int cmd_eos(const std::vector<std::string>& args);
int cmd_sweep(const std::vector<std::string>& args);

/// Parsed options: positional arguments plus "-o", "--bars", "--threads", "--plot" values and
/// flags; run's checkpoint options "--checkpoint-every" (s), "--checkpoint-file", "--restart";
/// sweep's "--set" (repeatable, in order) and "--seeds" (a whole number >= 1).
/// First word of the first comment line of a gauge record cut short (kolsky run stopped by a
/// signal or a numerical failure); kolsky analyze refuses such a record unless told.
inline constexpr const char* kIncompleteRecordMark = "INCOMPLETE run";

struct Options {
  std::vector<std::string> positional;
  std::string output, bars, gauges_csv, checkpoint_file, restart, plot_dir;
  std::vector<std::string> sets;  ///< sweep: each --set KEY=VALUES, as given
  double checkpoint_every = 0;
  int threads = 0;
  int seeds = 0;
  bool quiet = false;
  bool allow_incomplete = false;  ///< analyze: --allow-incomplete
};
/// `allowed` lists the option names this command takes (e.g. {"-o", "--quiet"}).
Options parse_options(const std::vector<std::string>& args, const std::vector<std::string>& allowed);

}  // namespace kolsky::app
