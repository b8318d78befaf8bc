// The functions of the experiment description (experiment.hpp), apart from the simulation that
// runs it: the scene layer (scene/) validates an ExperimentSpec with them, and links without
// the assemblies (the fuzz targets and the sanitizer build, fuzz/CMakeLists.txt, rely on it).
#include "shpb/experiment.hpp"

#include <string>
#include <variant>

#include "core/errors.hpp"
#include "dem/dem_system.hpp"  // kDemStepFraction

namespace kolsky::shpb {

double specimen_length(const SpecimenSpec& s) {
  struct {
    double operator()(const bar::ColumnParams& c) const { return c.length; }
    double operator()(const fe::FeSpecimenParams& f) const { return f.length; }
    double operator()(const dem::DemSpecimenParams& d) const { return d.packing.length; }
  } v;
  return std::visit(v, s);
}

double default_safety_factor(const SpecimenSpec& s) {
  const bool dem = std::holds_alternative<dem::DemSpecimenParams>(s);
  return dem ? kDefaultSafetyFactor * dem::kDemStepFraction : kDefaultSafetyFactor;
}

double specimen_diameter(const SpecimenSpec& s) {
  struct {
    double operator()(const bar::ColumnParams& c) const { return c.diameter; }
    double operator()(const fe::FeSpecimenParams& f) const { return 2.0 * f.radius; }
    double operator()(const dem::DemSpecimenParams& d) const { return d.packing.diameter; }
  } v;
  return std::visit(v, s);
}

namespace {

// What a grain specimen stepped beside FE parts cannot have (`with` names the FE parts): a
// hold (the FE parts step with the grains from t = 0), a preload on the supports (the FE
// parts carry the full contact forces), breakage (Chapter 3 has none).
void refuse_beside_fe_parts(const dem::DemSpecimenParams& d, const std::string& with) {
  if (d.walls.hold_until_loaded)
    throw InputError("", "specimen.hold_until_loaded",
                     "not supported with " + with + " (the FE parts step with the grains from t = 0): set it to false");
  if (d.walls.preload_on_supports)
    throw InputError("", "specimen.preload_on_supports",
                     "not supported with " + with + " (the FE parts carry the full contact forces): set it to false");
  if (d.breakage) throw InputError("", "specimen.breakage", "not supported with " + with);
}

}  // namespace

void check_fe_dem_supported(const ExperimentSpec& spec) {
  const dem::DemSpecimenParams& d = std::get<dem::DemSpecimenParams>(spec.specimen);
  if (spec.bar_kind != BarKind::meshed)
    throw InputError("", "specimen.tube", "a meshed tube around a dem specimen needs bars.kind = meshed");
  if (spec.incident.gauges.empty() || spec.transmission.gauges.empty())
    throw InputError("", "bars.kind", "meshed bars need a gauge on each bar (the face waves come from them)");
  refuse_beside_fe_parts(d, "bars.kind = meshed");
  if (spec.output.snapshot_interval > 0)
    throw InputError("", "output.snapshot_interval", "particle snapshots are not supported with bars.kind = meshed yet: set it to 0");
}

void check_fe_tube_supported(const ExperimentSpec& spec) {
  if (spec.strain_rate)
    throw InputError("", "specimen.tube", "a meshed tube is not supported with loading.kind = strain_rate");
  if (spec.bar_kind != BarKind::characteristic)
    throw InputError("", "specimen.tube",
                     "a meshed tube around a dem specimen needs bars.kind = meshed or characteristic");
  refuse_beside_fe_parts(std::get<dem::DemSpecimenParams>(spec.specimen), "a meshed tube");
}

}  // namespace kolsky::shpb
