// Axisymmetric mesh as structs of arrays: nodes (reference position, displacement, velocity,
// forces, lumped mass, fixed flags) and 4-node quads, built from structured r-z blocks. A block
// is one logical rectangle (specimen, tube, and later a meshed bar region); blocks do not share
// nodes, so bodies meet through contact. The node -> element incidence (CSR, ascending element
// order) lets element forces be gathered in a fixed order, independent of the thread count.
// Units: m, m/s, N, kg.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace kolsky::fe {

/// Nodal state, one entry per node. Velocities live at half steps (central differences).
struct Nodes {
  std::vector<double> r0, z0;            ///< reference coordinates
  std::vector<double> ur, uz;            ///< displacement at t^n
  std::vector<double> ur_prev, uz_prev;  ///< displacement at t^{n-1}
  std::vector<double> vr, vz;            ///< velocity at t^{n-1/2} (t^0 before the first step)
  std::vector<double> fr_int, fz_int;    ///< internal force at t^n (N)
  std::vector<double> fr_ext, fz_ext;    ///< external (contact, load) force at t^n (N)
  std::vector<double> mass;              ///< lumped (row-sum) mass, full ring (kg)
  std::vector<std::uint8_t> fixed_r, fixed_z;

  std::size_t size() const { return r0.size(); }
  double r(std::size_t i) const { return r0[i] + ur[i]; }
  double z(std::size_t i) const { return z0[i] + uz[i]; }
  /// Appends a node at rest at (r, z); nodes on the axis (r = 0) get u_r fixed.
  std::size_t add(double r, double z);
};

/// A structured block: (n_r + 1) x (n_z + 1) nodes, n_r x n_z elements, node (i, j) at the
/// i-th radial and j-th axial station.
struct Block {
  int first_node = 0, first_element = 0;
  int n_r = 0, n_z = 0;
  int node(int i, int j) const { return first_node + j * (n_r + 1) + i; }
  int element(int i, int j) const { return first_element + j * n_r + i; }
  int n_nodes() const { return (n_r + 1) * (n_z + 1); }
  int n_elements() const { return n_r * n_z; }
};

struct Mesh {
  Nodes nodes;
  std::vector<std::array<int, 4>> quads;  ///< counter-clockwise in (r, z)
  std::vector<int> incidence_start;       ///< CSR offsets, size n_nodes + 1
  std::vector<int> incidence;             ///< 4 * element + local node, ascending element

  /// Rebuilds the node -> element incidence; call after the last add_block.
  void build_incidence();
};

/// Adds a uniform block r in [r_in, r_out], z in [z_lo, z_hi] with n_r x n_z elements.
/// Throws std::invalid_argument for empty ranges, r_in < 0 or non-positive counts.
Block add_block(Mesh& mesh, double r_in, double r_out, double z_lo, double z_hi, int n_r, int n_z);

/// Ring area 2 pi * integral of N_i r dr of each node of a radial station list r_0 < r_1 < ...
/// (m^2): the tributary area of a face node, for face loads and penalty stiffnesses.
std::vector<double> ring_tributary_areas(const std::vector<double>& r);

/// Element nodal coordinates in the current configuration (t^n).
void current_coordinates(const Mesh& m, int e, std::array<double, 4>& r, std::array<double, 4>& z);

}  // namespace kolsky::fe
