// Error types shared by every module, and the exit codes the CLI maps them to.
//   InputError      -> exit 2: bad scene, bad CSV, bad option (names file, JSON path, rule).
//   NumericalError  -> exit 3: non-finite values or energy growth during a run.
#pragma once
#include <stdexcept>
#include <string>

namespace kolsky {

inline constexpr int kExitInputError = 2;
inline constexpr int kExitNumericalError = 3;

/// Bad input. what() is one line: "<file>: <json.path>: <rule broken>".
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string path, std::string rule)
      : std::runtime_error(format(file, path, rule)),
        file_(std::move(file)), path_(std::move(path)), rule_(std::move(rule)) {}
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  const std::string& rule() const { return rule_; }

 private:
  static std::string format(const std::string& f, const std::string& p, const std::string& r) {
    std::string s = f.empty() ? std::string("input") : f;
    if (!p.empty()) s += ": " + p;
    return printable(s + ": " + r);
  }
  /// Control characters (a NUL or a line break in a JSON key, a file name) as \u00XX: what()
  /// is one line, printed with %s, which would stop at a NUL or split at a line break.
  static std::string printable(const std::string& s) {
    static const char* hex = "0123456789abcdef";
    std::string out;
    for (const char c : s) {
      const auto u = static_cast<unsigned char>(c);
      if (u >= 0x20 && u != 0x7f) {
        out += c;
        continue;
      }
      out += "\\u00";
      out += hex[u >> 4];
      out += hex[u & 15];
    }
    return out;
  }
  std::string file_, path_, rule_;
};

/// A run stopped on request (SIGINT, SIGTERM), between two steps: handled like a numerical
/// failure (what was computed is kept, marked incomplete), with the exit code 128 + signal.
class StopRequested : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A run that blew up: NaN/Inf state, or energy growing past its bound. t is the simulated time.
class NumericalError : public std::runtime_error {
 public:
  NumericalError(const std::string& what, double t)
      : std::runtime_error(what), time_(t) {}
  double time() const { return time_; }

 private:
  double time_;
};

}  // namespace kolsky
