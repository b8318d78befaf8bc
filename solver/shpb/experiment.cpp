// The functions of the experiment description (experiment.hpp), apart from the simulation that
// runs it: the scene layer (scene/) validates an ExperimentSpec with them, and links without
// the assemblies (the fuzz targets and the sanitizer build, fuzz/CMakeLists.txt, rely on it).
#include "shpb/experiment.hpp"

#include <variant>

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

}  // namespace kolsky::shpb
