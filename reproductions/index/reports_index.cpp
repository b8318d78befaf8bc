// reports_index: `make reproduce` ends with it (harness/index.hpp).
//   reports_index --reports DIR [SET ...]
// writes DIR/index.md and DIR/index.html over the given sets (listed even when not run) and
// every other DIR/<set>/results.json. Exit 0 written, 1 usage, 2 a results.json unreadable.
// Whether the sets passed is the drivers' exit status, not this one's.
#include "core/errors.hpp"
#include "harness/index.hpp"

#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  std::string reports;
  std::vector<std::string> sets;
  bool usage_ok = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reports" && i + 1 < argc) reports = argv[++i];
    else if (a.empty() || a[0] == '-') usage_ok = false;
    else sets.push_back(a);
  }
  if (!usage_ok || reports.empty()) {
    std::fputs("usage: reports_index --reports DIR [SET ...]\n", stderr);
    return 1;
  }
  try {
    const int failing = kolsky::harness::write_index(reports, sets);
    std::printf("reports_index: %s/index.md and index.html (%d failing set%s)\n", reports.c_str(),
                failing, failing == 1 ? "" : "s");
  } catch (const kolsky::InputError& e) {
    std::fprintf(stderr, "reports_index: error: %s\n", e.what());
    return kolsky::kExitInputError;
  }
  return 0;
}
