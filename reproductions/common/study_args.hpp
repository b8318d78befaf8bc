// The command line of the study programs (reproductions/studies/): flags and their values read
// one at a time, a missing or malformed value sent to the program's usage (exit 1) instead of
// an uncaught std::stod exception.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace kolsky::repro {

class FlagReader {
 public:
  using Usage = void (*)(int exit_code);
  FlagReader(int argc, char** argv, Usage usage) : argc_(argc), argv_(argv), usage_(usage) {}
  /// Advances to the next argument; false after the last.
  bool next() {
    if (k_ + 1 >= argc_) return false;
    arg_ = argv_[++k_];
    return true;
  }
  const std::string& arg() const { return arg_; }
  /// The argument after the current flag.
  std::string value() {
    if (k_ + 1 >= argc_) fail("needs a value");
    return argv_[++k_];
  }
  double number() {
    const std::string v = value();
    try {
      std::size_t used = 0;
      const double x = std::stod(v, &used);
      if (used == v.size()) return x;
    } catch (const std::exception&) {
    }
    fail("needs a number, got '" + v + "'");
  }
  long integer() {
    const double x = number();
    if (x != static_cast<double>(static_cast<long>(x))) fail("needs a whole number");
    return static_cast<long>(x);
  }

 private:
  [[noreturn]] void fail(const std::string& why) {
    std::fprintf(stderr, "%s: %s\n", arg_.c_str(), why.c_str());
    usage_(1);
    std::abort();  // usage exits; never reached
  }
  int argc_;
  char** argv_;
  Usage usage_;
  int k_ = 0;
  std::string arg_;
};

}  // namespace kolsky::repro
