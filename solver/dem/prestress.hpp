// Pre-stress of a packed specimen (docs/dem.md, "Pre-stress"): the grains of a settled packing
// in the cylinder r < D/2, 0 < z < L are brought to a prescribed isotropic mean stress under
// the test's grain law (Hertz-Mindlin), so the specimen starts with a load-bearing contact
// network. A jammed packing at the target porosity carries almost no stress (~1 kPa), and a
// Hertz contact has no stiffness at zero force, so without this step the specimen starts far
// softer than a real, seated sand specimen (Chapter 4 reproduction, README).
// Procedure: a servo on one radius factor s for all grains (as PFC's servo walls, on the radii):
// the grains move with damped Hertz-Mindlin contacts against rigid frictionless Hertz walls,
// and every few steps s moves in proportion to the gap between the wall mean stress and the
// target, slowly enough for the network to follow (prestress.cpp gives the gain). SI units.
#pragma once
#include "dem/packing.hpp"

namespace kolsky::dem {

struct PrestressOutcome {
  double scale = 1;        ///< final radius factor s, -
  double mean_stress = 0;  ///< wall mean stress over the last servo window, Pa
  int stages = 0, steps = 0;  ///< servo intervals and steps run
  bool converged = false;  ///< |mean_stress / target - 1| <= tolerance
};

/// Pre-stresses `p` (grains in the cylinder of `in.diameter` x `in.length`, material
/// `in.material`) to `in.initial_stress` with the `in.prestress_*` parameters; radii, masses,
/// inertias and positions change, velocities end at zero. Precondition: in.initial_stress > 0.
PrestressOutcome prestress_packing(Particles& p, const PackingParams& in);

}  // namespace kolsky::dem
