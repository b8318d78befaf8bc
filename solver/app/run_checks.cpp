#include "app/run_checks.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bar/pulse.hpp"
#include "core/errors.hpp"

namespace kolsky::app {

namespace fs = std::filesystem;

namespace {

/// Whether a and b name the same file: the same inode when both exist, else the same path
/// once symbolic links and `..` are resolved.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  return fs::weakly_canonical(fs::absolute(a), ec) == fs::weakly_canonical(fs::absolute(b), ec);
}

void check_writable(const OutputPath& o) {
  std::error_code ec;
  if (o.path.empty()) throw InputError(o.option, "", "the file name must not be empty");
  if (fs::is_directory(o.path, ec))
    throw InputError(o.option, "", "'" + o.path + "' is a folder; give a file name");
  const fs::path dir = fs::absolute(o.path).parent_path();
  if (!fs::is_directory(dir, ec))
    throw InputError(o.option, "", "cannot write '" + o.path + "': the folder '" + dir.string() +
                                       "' does not exist");
  // The outputs are written under a temporary name in that folder, then renamed.
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(o.option, "", "cannot write '" + o.path + "': the folder '" + dir.string() +
                                       "' is not writable");
}

}  // namespace

void check_outputs(const std::vector<OutputPath>& outputs, const std::vector<std::string>& inputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const OutputPath& o = outputs[i];
    check_writable(o);
    for (const std::string& in : inputs)
      if (same_file(o.path, in))
        throw InputError(o.option, "", "'" + o.path + "' is an input of this command (" + in +
                                           "); writing it would replace it");
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(o.path, outputs[j].path))
        throw InputError(o.option, "", "'" + o.path + "' is also the output of " +
                                           outputs[j].option);
  }
}

std::vector<std::string> scene_inputs(const scene::Scene& sc) {
  std::vector<std::string> in{sc.file};
  // The CSV keys (docs/scene.md, "CSV paths"), absolute in the resolved scene.
  for (const char* key : {"/pulse/file", "/specimen/loading_curve", "/specimen/grain_size_curve",
                          "/loading/file"}) {
    const nlohmann::json::json_pointer p(key);
    if (sc.resolved.contains(p) && sc.resolved[p].is_string()) in.push_back(sc.resolved[p].get<std::string>());
  }
  return in;
}

double warn_probe_size(const shpb::SimulatedShpb& sim, const std::string& out) {
  const auto& s = sim.schedule();
  const double samples = std::floor(static_cast<double>(s.n_steps - 1) / s.sample_every) + 1;
  // The declared probes plus the analysis series (7) that join them in the run file.
  const double probes = static_cast<double>(sim.declared_probes().size()) + 7;
  const double bytes = probes * samples * 16.0;
  if (bytes > kProbeBytesWarning)
    std::fprintf(stderr,
                 "kolsky run: warning: the probes will take about %.3g GB, in memory during the run "
                 "and in %s (%.0f probes x %.0f samples); output.interval sets the sampling\n",
                 bytes / 1e9, out.c_str(), probes, samples);
  return bytes;
}

nlohmann::json report_initial_wall_stress(const shpb::SimulatedShpb& sim, const scene::Scene& sc,
                                          bool quiet) {
  const std::optional<FaceForces> s = sim.initial_wall_stress();
  if (!s) return nullptr;
  if (!quiet)
    std::fprintf(stderr, "kolsky run: %s: DEM packing: initial wall stress %.4g MPa (front), %.4g MPa (back)\n",
                 sc.file.c_str(), s->front / 1e6, s->back / 1e6);
  const auto& dem = std::get<dem::DemSpecimenParams>(sc.spec.specimen);
  const double worst = std::max(std::fabs(s->front), std::fabs(s->back));
  const double peak = sc.spec.strain_rate ? 0.0 : bar::peak_stress(sc.spec.pulse);
  if (peak > 0 && worst > kInitialWallStressWarning * peak && !(dem.packing.initial_stress > 0))
    std::fprintf(stderr,
                 "kolsky run: warning: %s: the packing starts with %.4g MPa on an end wall, %.0f %% of "
                 "the pulse's %.4g MPa (warned above %.0f %%): the bars carry it from t = 0 and the "
                 "energy check may stop the run while it relaxes; smaller grains "
                 "(specimen.upscale) pack with less, specimen.preload_on_supports = true puts it "
                 "on the bar supports\n",
                 sc.file.c_str(), worst / 1e6, 100 * worst / peak, peak / 1e6,
                 100 * kInitialWallStressWarning);
  return {{"front", s->front}, {"back", s->back}};
}

}  // namespace kolsky::app
