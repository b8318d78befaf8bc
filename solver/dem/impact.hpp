// Two-body impact runner for the contact-law verifications (Hertz closed forms, Chung & Ooi
// 2011 benchmark): steps a DemSystem until the contact of particle 0 with particle 1 (or, for
// a single particle, with plane 0) has formed and ended, recording peak normal force, maximum
// overlap and contact duration. Start and end times are interpolated linearly between steps on
// the overlap, and the peaks are the vertex of a parabola through the three samples around the
// largest, so that sampling adds no O(dt^2) error of its own to the integrator's.
#pragma once

#include "dem/dem_system.hpp"

namespace kolsky::dem {

struct ImpactRecord {
  double peak_force = 0;    ///< peak normal contact force (parabolic fit), N
  double max_overlap = 0;   ///< peak overlap (parabolic fit), m
  double contact_time = 0;  ///< interpolated duration of the contact, s
  bool separated = false;   ///< the contact formed and ended within max_steps
  int steps = 0;            ///< steps taken
};

/// Overlap of the watched contact: particles 0 and 1 if there are two or more, else particle 0
/// with plane 0 (m; negative when apart).
double watched_overlap(const DemSystem& sys);

/// Steps with dt until the watched contact has formed and ended, or max_steps.
ImpactRecord run_impact(DemSystem& sys, double dt, int max_steps);

}  // namespace kolsky::dem
