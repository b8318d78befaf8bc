// Walls of the DEM specimen, each with its own contact law (WallLaw): infinite planes moving
// along their normal (fixed, prescribed velocity history, or driven from outside by a bar
// face), and the inner surface of a cylinder parallel to z (the confining tube), rigid or
// radially compliant as a thin elastic ring with one radial degree of freedom: hoop stiffness
// K = 2 pi H E t / R (p = E t u / R^2) and mass rho 2 pi R t H (docs/dem.md says why one DOF
// rather than a spring per contact). Planes and cylinders are one family for the contact
// lists: WallSlots is its one slot rule. SI units.
#pragma once
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "core/specimen_geometry.hpp"
#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace kolsky::dem {

/// Piecewise-linear speed history s'(t) along a plane's normal (m/s at times in s), held
/// constant outside the table. time strictly increasing, same length as speed (>= 1).
struct VelocityHistory {
  std::vector<double> time, speed;

  double at(double t) const;
  /// Exact integral of the piecewise-linear speed over [t0, t1] (m).
  double displacement(double t0, double t1) const;
};

struct FixedPlane {};
struct PrescribedPlane {
  VelocityHistory velocity;
};
/// Position and speed set from outside each step (DemSystem::drive_plane).
struct DrivenPlane {};
using PlaneMotion = std::variant<FixedPlane, PrescribedPlane, DrivenPlane>;

/// Plane through `point` (at t = 0) with unit `normal` pointing into the particle region. It
/// moves along the normal by offset s(t); contacts push particles along +normal.
struct PlaneWall {
  Vec3 point;
  Vec3 normal{0, 0, 1};
  PlaneMotion motion = FixedPlane{};
  WallLaw law = linear_spring(LinearParams{});  ///< Table 4.1 wall contact
};

/// A deformable wall's shape, set from outside each step (DemSystem::drive_plane_profile,
/// drive_cylinder; the FE-DEM coupling, docs/coupling.md): piecewise linear in a station s
/// (a plane normal to z: the distance from the z axis; a cylinder: z), held constant beyond
/// the first and last stations. offset: displacement of the surface along the wall's normal
/// into the grains (plane) or outward radial displacement (cylinder), m; normal_speed its rate,
/// m/s; tangential_speed the surface's velocity along s (radial for a plane, axial for a
/// cylinder), m/s, which only friction and damping see. The normal stays the wall's own (z, or
/// radial): the surface's slope d offset / ds (~1e-4 in an SHPB) tilts it by that angle, which
/// is neglected (docs/coupling.md). Stations strictly increasing, all arrays of one size >= 2.
struct WallProfile {
  std::vector<double> station, offset, normal_speed, tangential_speed;

  struct Sample { double offset = 0, normal_speed = 0, tangential_speed = 0; };
  /// The linear interpolation at s (held beyond the ends).
  Sample at(double s) const;
  /// Segment index k (station[k] <= s < station[k+1], clamped to [0, n-2]) and the weight w of
  /// node k+1 (1 - w on node k; 0 or 1 beyond the ends): the linear shape functions.
  std::pair<int, double> segment(double s) const;
};
/// Throws kolsky::InputError (path) unless the arrays have one size >= 2, the stations
/// increase strictly and every value is finite.
void validate(const WallProfile& p, const char* path);

/// Thin elastic confining tube (radial compliance of CylinderWall).
struct TubeCompliance {
  double youngs_modulus = 200e9;  ///< E of the tube, Pa
  double thickness = 0.005;       ///< wall thickness t, m
  double density = 8100;          ///< kg/m^3
  double height = kSpecimenLength; ///< H, length over which the specimen pressure acts, m
  /// Radial stiffness per unit inner-wall area p / u (Pa/m), e.g. a thick tube's Lame value
  /// (fe::lame_wall_stiffness); 0: the thin-wall E t / R^2.
  double wall_stiffness = 0;

  /// K = 2 pi R H k_w (N/m) for inner radius R: k_w = wall_stiffness, or E t / R^2 (thin wall,
  /// K = 2 pi H E t / R).
  double radial_stiffness(double radius) const;
  /// m = rho 2 pi R t H (kg).
  double radial_mass(double radius) const;
};

/// Inner surface of a cylinder of radius `radius` around the axis x = cx, y = cy (parallel to
/// z), infinitely long; particles live inside. Rigid unless `compliance` is set.
struct CylinderWall {
  double cx = 0, cy = 0;
  double radius = kSpecimenDiameter / 2;
  std::optional<TubeCompliance> compliance;
  WallLaw law = linear_spring(LinearParams{});  ///< Table 4.1 wall contact
};

enum class WallKind { plane, cylinder };

/// The one slot rule of a DemSystem's walls: every wall-contact list, history, resultant and
/// checkpoint entry is indexed by a wall slot, planes first (plane k at slot k), then
/// cylinders (cylinder k at slot n_planes + k). Built from DemSystem::n_planes() and
/// n_cylinders(); nothing else may spell the rule out.
struct WallSlots {
  int n_planes = 0, n_cylinders = 0;

  int count() const { return n_planes + n_cylinders; }
  /// The slot of wall k of the kind.
  int slot(WallKind kind, int k) const { return kind == WallKind::plane ? k : n_planes + k; }
  /// The kind and index (among its kind) of the wall in `slot`.
  WallKind kind(int slot) const { return slot < n_planes ? WallKind::plane : WallKind::cylinder; }
  int index(int slot) const { return slot < n_planes ? slot : slot - n_planes; }
};

/// Throws kolsky::InputError for a degenerate wall (zero normal, radius <= 0, bad history,
/// invalid law parameters: path.law.<field>).
void validate(const PlaneWall& w, const char* path);
void validate(const CylinderWall& w, const char* path);

}  // namespace kolsky::dem
