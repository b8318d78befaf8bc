// The 14-sphere apollonian replacement of a broken grain (dissertation Sec. 5.2.3, Table 5.3,
// after Ciantia et al. 2015): radii and centres in units of the parent radius R, in a frame whose
// z' axis is the direction of the parent's largest contact force, so that the three largest
// daughters (#1-3, z' = 0) lie in the plane perpendicular to that force. The set retains
// sum (r/R)^3 = 0.5338 of the parent's volume; the rest is "lost" to the grain-size curve as
// fines (Eq. 5.16, breakage_ledger.hpp). Pure geometry: no particle state. Lengths in m.
#pragma once
#include <array>
#include <cstddef>

#include "dem/vec3.hpp"

namespace kolsky::dem {

/// One daughter sphere: centre and radius (m, or units of R in kApollonianTable).
struct Daughter {
  Vec3 centre;
  double radius = 0;
};

inline constexpr std::size_t kApollonianCount = 14;

/// Table 5.3 as printed (r/R; x'/R, y'/R, z'/R), numbered #1-#14 in the text = index 0-13 here.
/// The numbers are rounded to 1e-4: every daughter is internally tangent to the parent to
/// 1e-4 (|c| + r = 1.0000, #7/#8 0.9998) and the largest pairwise overlap is 5.8e-5 R
/// (targets.md 5a), which the tests measure.
inline constexpr std::array<Daughter, kApollonianCount> kApollonianTable{{
    {{0.0, 0.5359, 0.0}, 0.4641},        // #1  three largest: the plane z' = 0
    {{-0.4641, -0.2679, 0.0}, 0.4641},   // #2
    {{0.4641, -0.2679, 0.0}, 0.4641},    // #3
    {{-0.6720, 0.3880, 0.0}, 0.2240},    // #4  smallest: d_max of the fines (Eq. 5.16)
    {{0.6720, 0.3880, 0.0}, 0.2240},     // #5
    {{0.0, -0.7760, 0.0}, 0.2240},       // #6
    {{0.0, 0.0, 0.6339}, 0.3659},        // #7  on the force axis
    {{0.0, 0.0, -0.6339}, 0.3659},       // #8
    {{0.0, -0.5942, 0.4456}, 0.2573},    // #9
    {{0.5146, 0.2971, 0.4456}, 0.2573},  // #10
    {{-0.5146, 0.2971, 0.4456}, 0.2573}, // #11
    {{0.0, -0.5942, -0.4456}, 0.2573},   // #12
    {{0.5146, 0.2971, -0.4456}, 0.2573}, // #13
    {{-0.5146, 0.2971, -0.4456}, 0.2573} // #14
}};

/// sum over Table 5.3 of (r/R)^3 = 0.533784: the volume (mass) fraction the daughters keep.
double retained_volume_fraction();
/// 1 - retained_volume_fraction() = 0.466216: the fraction that leaves as fines (the "47 %").
double lost_volume_fraction();
/// Smallest r/R of Table 5.3 (0.2240, daughters #4-#6); 2 x this x R is d_max of Eq. 5.16.
double smallest_daughter_ratio();
/// Volume-weighted centroid of the daughters, sum r^3 c / sum r^3, in units of R. Zero for an
/// exact apollonian packing; for the rounded table it is ~1e-5 (measured in the tests), which
/// is the linear-momentum error a rigid-body velocity v + omega x r would carry.
Vec3 retained_centroid();

/// Right-handed orthonormal frame {e1, e2, e3} with e3 = axis / |axis|, turned by spin_angle
/// (rad) about e3. Works for any finite non-zero axis (also tiny or coordinate-aligned ones:
/// the axis is scaled by its largest component before normalising, and e1 is built from the
/// coordinate axis least aligned with e3). Throws std::invalid_argument for a zero or
/// non-finite axis, or a non-finite angle.
std::array<Vec3, 3> force_frame(Vec3 force_axis, double spin_angle);

/// The 14 daughters of a parent of centre `parent_centre` and radius `parent_radius` (m, > 0):
/// Table 5.3 with x', y', z' mapped onto force_frame(force_axis, spin_angle), scaled by R.
/// The three largest centres lie in the plane through the parent's centre perpendicular to
/// force_axis; the sign of the axis does not matter geometrically (the table is symmetric
/// under z' -> -z'). Throws std::invalid_argument as force_frame, or for a radius that is not
/// finite and > 0.
std::array<Daughter, kApollonianCount> place_daughters(Vec3 parent_centre, double parent_radius,
                                                       Vec3 force_axis, double spin_angle);

}  // namespace kolsky::dem
