// libFuzzer target: a gauge record (kolsky analyze GAUGES.csv --bars BARS.json) from bytes to
// the specimen history, as cmd_analyze does it: the CSV reader, the record rules
// (process_gauges: row errors reported at their file line), pulse detection, window
// separation, the shift to the faces without and with the dispersion correction, and the
// analysis. The bars are data/examples/bars_song2009.json. Corpus: fuzz/corpus/gauges/.
// Allowed outcomes: InputError (exit 2) and NumericalError (exit 3, a non-finite noise level).
#include <sstream>
#include <string>

#include "fuzz_support.hpp"
#include "io/csv.hpp"
#include "scene/scene.hpp"
#include "shpb/analysis.hpp"
#include "shpb/gauge_processing.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace kolsky;
  static const scene::BarsFile bars =
      scene::load_bars_file(KOLSKY_SOURCE_DIR "/data/examples/bars_song2009.json");
  const std::string file = "fuzz.csv";
  fuzz::expect_input_error_only([&] {
    std::istringstream in{std::string(fuzz::as_text(data, size))};
    const io::CsvTable csv = io::parse_csv(in, file);
    if (csv.columns.size() < 3) return;  // cmd_analyze: InputError "needs 3 columns"
    const shpb::GaugeRecord rec{csv.columns[0], csv.columns[1], csv.columns[2]};
    for (const bool dispersion : {false, true}) {
      shpb::GaugeOptions opt = bars.gauge;
      opt.dispersion_correction = dispersion;
      shpb::FaceWaves waves;
      try {
        waves = shpb::process_gauges(rec, bars.setup, opt);
      } catch (const shpb::GaugeRowError& e) {
        throw InputError(file, "line " + std::to_string(csv.lines.at(e.row)), e.rule);
      } catch (const std::invalid_argument& e) {
        throw InputError(file, "", e.what());
      } catch (const NumericalError&) {
        return;
      }
      (void)shpb::analyze(waves, bars.setup, bars.analysis);
    }
  });
  return 0;
}
