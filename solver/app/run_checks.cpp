#include "app/run_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bar/pulse.hpp"

namespace kolsky::app {

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
