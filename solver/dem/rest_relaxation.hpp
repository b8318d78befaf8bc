// The last stage of a DEM specimen's preparation: the packed grains relax, between the run's
// own walls held fixed, under the run's own grain law, rolling retardation and wall laws, until
// they are at rest (docs/dem.md, "A specimen at rest"). The packing ends under other laws (its
// pre-stress locks rotation and has frictionless walls; its growth uses linear springs), and a
// run used to start from its positions with no tangential history: a network held by friction
// then has no friction at t = 0 and falls apart (Chapter 4 N = 2, walls fixed, no load: Z 2.41
// -> 0.04 in 200 us, the same in LIGGGHTS 3.8; issue 31). Relaxed here and handed to the run
// with its contact histories (DemSystem::seed_contact_history), the specimen starts in an
// equilibrium its own law holds.
// Dissipation: kinetic damping (Cundall's dynamic relaxation: all velocities are set to zero
// each time the grains' kinetic energy passes a peak), which removes energy without adding a
// force to the law, so the state it ends in is a static equilibrium of the run's law alone
// (the law's dashpots, if any, act as well). The walls stay fixed: the porosity is the
// packing's, the stress is whatever the relaxed network carries (reported). SI units.
#pragma once
#include <functional>

#include "dem/dem_system.hpp"

namespace kolsky::dem {

struct RestRelaxationParams {
  /// Converged when the largest kinetic energy of the last check window is below this fraction
  /// of the elastic energy the contacts held when the relaxation began, -. The reference is
  /// the start's energy, not the current one: a network the run's law cannot hold (Chapter 4 at
  /// n = 0.44 with free rotation) gives up nearly all of it (4.9e-5 -> 6e-14 J at N = 4), and a
  /// criterion on the current energy then never converges. 1e-6: test_dem_rest.cpp.
  double kinetic_tolerance = 1e-6;
  int check_steps = 200;     ///< steps per check window
  /// The most steps the relaxation takes (then: not converged). 40,000 left the Chapter 4 N = 2
  /// specimen with rotation locked at 4.6x the tolerance (reproductions/chapter4/README.md).
  int max_steps = 100000;
  double step_fraction = kDemStepFraction;  ///< dt = this x stable_dt()
};

struct RestRelaxationOutcome {
  int steps = 0;                  ///< steps taken
  int quenches = 0;               ///< kinetic-energy peaks at which the grains were stopped
  bool converged = false;         ///< kinetic_tolerance reached within max_steps
  double kinetic_to_elastic = 0;  ///< the last window's peak kinetic energy over elastic_before, -
  double elastic_before = 0, elastic_after = 0;  ///< contacts' elastic energy, J
  double coordination_before = 0, coordination_after = 0;  ///< 2 x touching pairs / grains
};

/// Throws kolsky::InputError ("dem.rest.<member>") unless kinetic_tolerance > 0, check_steps
/// and max_steps >= 1 and step_fraction in (0, 1].
void validate(const RestRelaxationParams& p);

/// Relaxes `sys` as it is (walls as they are, not moved) until at rest; ends with every
/// velocity and spin zero. Throws kolsky::InputError ("dem.rest...") for bad parameters.
/// `on_window`, if set, observes the outcome so far after every check window (progress: a
/// large specimen relaxes for minutes); it is not part of the result.
RestRelaxationOutcome relax_to_rest(
    DemSystem& sys, const RestRelaxationParams& p,
    const std::function<void(const RestRelaxationOutcome&)>& on_window = {});

}  // namespace kolsky::dem
