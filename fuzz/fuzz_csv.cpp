// libFuzzer target: the numeric CSV reader (io/csv.hpp) and the rules of the tables a scene
// names (scene/csv_load.hpp): a tabulated pulse, a strain-rate history, a loading curve.
// Each rule set runs on every table that parses. Corpus: fuzz/corpus/csv/.
#include <sstream>
#include <string>

#include "fuzz_support.hpp"
#include "io/csv.hpp"
#include "scene/csv_load.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace kolsky;
  io::CsvTable t;
  bool parsed = false;
  fuzz::expect_input_error_only([&] {
    std::istringstream in{std::string(fuzz::as_text(data, size))};
    t = io::parse_csv(in, "fuzz.csv");
    parsed = true;
  });
  if (!parsed) return 0;
  for (size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c].size() != t.lines.size()) __builtin_trap();  // every row has its line
  fuzz::expect_input_error_only([&] { scene::pulse_table(t, "fuzz.csv"); });
  fuzz::expect_input_error_only([&] { scene::strain_rate_table(t, "fuzz.csv"); });
  fuzz::expect_input_error_only([&] { scene::loading_curve(t, "fuzz.csv"); });
  return 0;
}
