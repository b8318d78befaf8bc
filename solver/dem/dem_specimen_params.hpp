// Everything needed to build a DEM specimen for the bars: the packing (grain-size curve,
// upscaling already applied, porosity, cylinder, seed, grain material), the grain contact law
// (Hertz-Mindlin, Sec. 4.3 / Table 4.1), the walls and the integrator options (rolling
// retardation, Eqs. 4.12-4.14).
#pragma once
#include "dem/contact_hertz_mindlin.hpp"
#include "dem/dem_specimen.hpp"
#include "dem/packing.hpp"
#include "dem/packing_cache.hpp"

namespace kolsky::dem {

struct DemSpecimenParams {
  PackingParams packing;          ///< curve (upscaled), porosity, diameter, length, seed, material
  HertzMindlinParams contact;     ///< grain-grain friction and restitution
  SpecimenWalls walls;            ///< end planes and tube (length/radius follow the packing)
  DemOptions options;             ///< rolling retardation, skin, dt safety
  std::string packing_cache;      ///< cache directory (packing_cache.hpp); "" = none
};

/// Packs the grains (generate_packing, through the cache when p.packing_cache is set) and
/// builds the specimen between the two end planes.
inline DemSpecimen make_dem_specimen(const DemSpecimenParams& p) {
  PackingResult packed = cached_packing(p.packing, p.packing_cache).result;
  SpecimenWalls walls = p.walls;
  walls.length = p.packing.length;
  walls.radius = 0.5 * p.packing.diameter;
  std::vector<Material> materials{p.packing.material};
  return DemSpecimen(std::move(packed.particles), materials, HertzMindlin(materials, p.contact),
                     walls, p.options);
}

}  // namespace kolsky::dem
