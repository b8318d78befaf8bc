// libFuzzer target: a scene file (kolsky run SCENE.json) from bytes to the validated
// ExperimentSpec, as load_scene does it: JSON syntax (duplicate keys, number range), the
// schema walk, cross-key rules, and the CSV tables a scene names (pulse.file, loading.file,
// specimen.grain_size_curve ...), which resolve against data/examples/ so that the seed
// scenes' relative paths find the project's own tables. Corpus: fuzz/corpus/scene/.
#include <nlohmann/json.hpp>

#include "fuzz_support.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace kolsky;
  fuzz::expect_input_error_only([&] {
    const nlohmann::json j = scene::parse_json_text(fuzz::as_text(data, size), "fuzz.json");
    const scene::Scene s =
        scene::parse_scene(j, "fuzz.json", KOLSKY_SOURCE_DIR "/data/examples");
    (void)s.resolved.dump();  // written into every output
  });
  return 0;
}
