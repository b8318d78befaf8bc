// The coupling layer: where two physics modules meet below shpb, so that the SHPB assemblies
// only sequence calls and no physics module includes another (docs/architecture.md). This
// header holds the two halves of the FE surface <-> DEM wall exchange of the coupled FEM-DEM
// assembly (coupling/fe_dem.hpp; docs/coupling.md):
//   FE -> DEM: an FE surface's nodes at t^n become a DEM WallProfile (dem/walls.hpp), the
//   surface's displacement along its normal as a piecewise-linear function of the station
//   (r for a bar face, z for the tube wall), so that a grain meets the surface where the FE
//   surface is at the grain's station (linear interpolation between the two nodes around it).
//   DEM -> FE: each grain-wall contact force, reversed, is split into its radial, axial and
//   circumferential parts at the grain; the radial and axial parts are the ring loads of the
//   axisymmetric body, distributed to the segment's two nodes by the same linear shape
//   functions (the sum over the two nodes is the contact's force exactly: b = w F, a = F - b);
//   the circumferential part and the lateral resultant cannot act on an axisymmetric body and
//   are tallied, not applied (RingLoads).
// Units SI; (r, z) in the FE body's axisymmetric half-plane; forces are the totals over the
// ring a node stands for, signed along +r and +z.
#pragma once
#include <vector>

#include "dem/dem_system.hpp"
#include "dem/vec3.hpp"
#include "dem/walls.hpp"
#include "fe/mesh.hpp"

namespace kolsky::coupling {

/// Which way a bar face faces the grains: the incident face (normal +z, at z = 0 initially)
/// or the transmission face (normal -z, at z = L_s).
enum class FaceSide { front = +1, back = -1 };

/// The bar face through `face` (node indices, ascending r) at t^n as the profile of a DEM
/// plane with normal side x z: stations r, offset side x u_z, normal_speed side x v_z,
/// tangential_speed v_r (velocities at t^{n-1/2}, the latest the central-difference FE has
/// at t^n; the FE contacts use the same lag).
dem::WallProfile face_profile(const fe::Nodes& nodes, const std::vector<int>& face, FaceSide side);
/// The tube's inner wall through `wall` (ascending z) at t^n as the profile of a DEM
/// cylinder: stations z, offset u_r, normal_speed v_r, tangential_speed v_z.
dem::WallProfile tube_profile(const fe::Nodes& nodes, const std::vector<int>& wall);

/// Ring loads on one surface's nodes, and what the axisymmetric body cannot take.
struct RingLoads {
  std::vector<double> f_r, f_z;   ///< per node (N)
  dem::Vec3 resultant;            ///< 3-D resultant of the forces on the surface (N)
  double axial = 0, radial = 0;   ///< sums of the applied axial and radial parts (N)
  double torque_z = 0;            ///< moment about the z axis of the circumferential parts (N m)
  double circumferential = 0;     ///< sum |f_theta| (N)
  int contacts = 0;

  explicit RingLoads(std::size_t n_nodes = 0) : f_r(n_nodes, 0.0), f_z(n_nodes, 0.0) {}
};

/// Adds the force `on_surface` (N, 3-D: minus the grain's contact force) of a contact at the
/// grain centre x, station s on the surface whose nodes have stations profile.station.
void add_contact(RingLoads& loads, const dem::WallProfile& profile, double s, const dem::Vec3& x,
                 const dem::Vec3& on_surface);

/// The ring loads of wall `slot`'s contacts in `sys`'s last force evaluation on the surface
/// whose shape `profile` is: each grain's contact force reversed, at the grain's station (its
/// distance from the axis on a plane face, its z on a cylinder).
RingLoads wall_ring_loads(const dem::DemSystem& sys, int slot, const dem::WallProfile& profile, bool plane);

/// The grain springs' limit on a surface's nodes (s, raw): min over the nodes of
/// sqrt(m / (N k)) of the wall law's stiffest spring, a node of mass m and tributary area A
/// carrying at most N = max(1, A / (pi r_min^2)) grains. Throws InputError
/// ("specimen.wall_normal_stiffness") for a wall law that is not a linear spring.
double surface_node_dt(const dem::WallLaw& law, const fe::Nodes& nodes, const std::vector<int>& surface,
                       const std::vector<double>& areas, double r_min);

}  // namespace kolsky::coupling
