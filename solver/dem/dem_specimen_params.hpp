// Everything needed to build a DEM specimen for the bars: the packing (grain-size curve,
// upscaling already applied, porosity, cylinder, seed, grain material), the grain contact law
// (one of the ContactLaw family: Hertz-Mindlin, Sec. 4.3 / Table 4.1, by default; linear;
// LS-DYNA's linear DES law, Eqs. 3.1-3.4 / Table 3.2), the walls and the integrator options
// (rolling retardation, Eqs. 4.12-4.14), and the caller's names of these inputs for errors.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "dem/contact_law.hpp"
#include "dem/dem_specimen.hpp"
#include "dem/packing.hpp"
#include "dem/packing_cache.hpp"

namespace kolsky::dem {

/// An input's name in the caller's terms. The physics names its inputs by its own paths
/// ("dem.contact_law.normk", "dem.walls.plane.law.normal_stiffness", "dem.packing.curve");
/// a caller that knows them by other names (the scene: "specimen.normk") lists the pairs, and
/// make_dem_specimen rethrows an InputError whose path is `internal` or lies under it
/// ("internal.x", "internal[3]") with the path `external`, the longest `internal` winning,
/// file and rule kept. Paths that match nothing pass unchanged.
struct InputName {
  std::string internal, external;
};

struct DemSpecimenParams {
  PackingParams packing;          ///< curve (upscaled), porosity, diameter, length, seed, material
  ContactLawParams contact;       ///< grain-grain law and its parameters (Hertz-Mindlin default)
  SpecimenWalls walls;            ///< end planes and tube (length/radius follow the packing)
  DemOptions options;             ///< rolling retardation, skin, dt safety
  PackingStore packing_store;     ///< where packings are reused (packing_cache.hpp); empty = none
  /// Particle breakage (Sec. 5.2.3; docs/breakage.md); none: no grain ever breaks, and the
  /// specimen is bitwise what it was before breakage existed. Needs the Hertz-Mindlin law.
  std::optional<BreakageParams> breakage;
  /// Whether stable_dt() covers, from the start, the smallest daughter the comminution limit
  /// allows (DemOptions::smallest_radius_to_come). True for a run whose dt is fixed for its
  /// whole length; false for one that asks the limit again after every break and refines its
  /// dt (time_loop::refine; the strain-rate walls with time.dt = 0): its step then follows
  /// the smallest grain actually present (docs/breakage.md, "Time step").
  bool step_for_daughters_up_front = true;
  /// The preparation's last stage (rest_relaxation.hpp; docs/dem.md, "A specimen at rest"):
  /// the packed grains relax to rest between the fixed walls under the run's own laws, and the
  /// run starts from that state with its contact histories. None: the run starts from the
  /// packing's positions with no tangential history (what every scene did before).
  std::optional<RestRelaxationParams> rest;
  std::vector<InputName> input_names;  ///< for errors while building (empty: physics names)
};

/// Packs the grains (generate_packing, through p.packing_store when it has one) and
/// builds the specimen between the two end planes with the law p.contact selects. An
/// InputError thrown meanwhile is renamed through p.input_names (rename_input_error).
DemSpecimen make_dem_specimen(const DemSpecimenParams& p);

/// `e` with its path in the names of `names` (InputName's rule); `e` itself when none matches.
kolsky::InputError rename_input_error(const kolsky::InputError& e,
                                      const std::vector<InputName>& names);

}  // namespace kolsky::dem
