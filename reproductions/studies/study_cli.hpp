// What the study programs (reproductions/studies/) share around their own work: the usage text
// and the walk over their flags (FlagReader, common/study_args.hpp), with --help / -h and an
// argument a program does not take handled alike in all of them; and the protocol of a
// resumable study: a case's result is written last and atomically, so that its file exists
// only for a case that ran to its end, and a rerun skips that case.
// Exit codes the programs share: 0 done (or done before), 1 a wrong command line (the usage on
// stderr), 3 a case that failed.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/study_args.hpp"

namespace kolsky::repro {

/// Prints `text` on stdout when it was asked for (code 0), else on stderr; exits with `code`.
[[noreturn]] void exit_with_usage(int code, const char* text);

/// Takes one argument of the command line, reading any value it has through the reader;
/// false for an argument the program does not take.
using FlagHandler = std::function<bool(const std::string& arg, FlagReader& r)>;

/// Walks argv: --help and -h call usage(0), every other argument goes to `flag`, and one that
/// `flag` does not take calls usage(1).
void read_flags(int argc, char** argv, FlagReader::Usage usage, const FlagHandler& flag);

/// Line-buffered stdout: a study runs for minutes to hours, and its progress lines should reach
/// a log file as they are printed.
void line_buffered_stdout();

/// The packing cache's folder: `given`, or OUT/packing_cache when none is given, as an absolute
/// path (a scene resolves relative paths against its own folder, where the cache must not land).
std::string packing_cache_dir(const std::string& given, const std::string& out);

/// Starts the one case of a call: creates `out` and returns OUT/LABEL, the stem of the case's
/// files; nothing, after saying so on stdout, when OUT/LABEL.json shows the case done before.
std::optional<std::string> start_case(const std::string& out, const std::string& label);

/// Writes `j` (one-space indent, a final newline) to `path` through a temporary file.
void write_json_atomic(const std::string& path, const nlohmann::json& j);

/// Ends the case of start_case: its summary STEM.json, written after every other file of the
/// case, since it marks the case done.
void finish_case(const std::string& stem, const nlohmann::json& summary);

/// Says on stderr that the case `label` failed and why; returns the exit code for it (3).
int case_failed(const std::string& label, const std::string& why);

}  // namespace kolsky::repro
