// libFuzzer target: a BARS.json (kolsky analyze --bars) from bytes to the BarsFile, as
// load_bars_file does it: JSON syntax, the "bars" schema, the geometry rule.
// Corpus: fuzz/corpus/bars/.
#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace kolsky;
  fuzz::expect_input_error_only([&] {
    const nlohmann::json j = scene::parse_json_text(fuzz::as_text(data, size), "BARS.json");
    const scene::BarsFile f = scene::parse_bars_file(j, "BARS.json");
    (void)f.resolved.dump();
  });
  return 0;
}
