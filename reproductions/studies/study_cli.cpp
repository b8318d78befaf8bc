// The study programs' shared command line and case files (study_cli.hpp).
#include "studies/study_cli.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/atomic_file.hpp"

namespace kolsky::repro {

void exit_with_usage(int code, const char* text) {
  std::fputs(text, code ? stderr : stdout);
  std::exit(code);
}

void read_flags(int argc, char** argv, FlagReader::Usage usage, const FlagHandler& flag) {
  FlagReader r(argc, argv, usage);
  while (r.next()) {
    const std::string& a = r.arg();
    if (a == "--help" || a == "-h") usage(0);
    if (!flag(a, r)) usage(1);
  }
}

void line_buffered_stdout() { std::setvbuf(stdout, nullptr, _IOLBF, 0); }

std::string packing_cache_dir(const std::string& given, const std::string& out) {
  return std::filesystem::absolute(given.empty() ? out + "/packing_cache" : given).string();
}

std::optional<std::string> start_case(const std::string& out, const std::string& label) {
  const std::string stem = out + "/" + label;
  std::filesystem::create_directories(out);
  if (std::filesystem::exists(stem + ".json")) {
    std::printf("%s: done before (%s.json); not rerun\n", label.c_str(), stem.c_str());
    return std::nullopt;
  }
  return stem;
}

void write_json_atomic(const std::string& path, const nlohmann::json& j) {
  write_file_atomic(path, j.dump(1) + "\n");
}

void finish_case(const std::string& stem, const nlohmann::json& summary) {
  write_json_atomic(stem + ".json", summary);
}

int case_failed(const std::string& label, const std::string& why) {
  std::fprintf(stderr, "%s: failed: %s\n", label.c_str(), why.c_str());
  return 3;
}

}  // namespace kolsky::repro
