// The coupling layer: where two physics modules meet below shpb, so that the SHPB assemblies
// only sequence calls and no physics module includes another (docs/architecture.md). Empty of
// code today; this header fixes the data of the one coupling planned, assembly (c) of
// shpb/assembly.hpp: DEM grains between meshed FE bars inside an FE tube (coupled FEM-DEM).
//   Why nodal data: the 1-D face interface (core/specimen_coupling.hpp, four scalars in, two
//   out) assumes plane rigid faces. Meshed bar faces bulge (Pochhammer-Chree, radial inertia)
//   and the tube wall expands, so the grains must see each surface node where it is.
//   Protocol, each step n (both integrators central differences at t^n): FE surface nodes at
//   t^n -> DEM walls (surfaces of revolution through the node polylines) -> grain contact
//   forces at t^n -> ring-integrated nodal forces on the FE surface -> FE step, DEM step.
//   Units SI; (r, z) in the FE body's axisymmetric half-plane; forces are the totals over the
//   ring a node stands for, signed along +r and +z.
// A coupling/*.cpp will also need adding to the glob of solver/CMakeLists.txt.
#pragma once
#include <vector>

namespace kolsky::coupling {

/// One FE contact surface at t^n: a node polyline in the (r, z) half-plane, in surface order.
struct SurfaceMotion {
  std::vector<int> nodes;           ///< FE node indices
  std::vector<double> r, z;         ///< positions, m
  std::vector<double> v_r, v_z;     ///< velocities, m/s
};

/// What the grains exert on that surface at t^n, per node of SurfaceMotion::nodes (N).
struct SurfaceLoads {
  std::vector<double> f_r, f_z;
};

}  // namespace kolsky::coupling
