// Axisymmetric (r-z) 4-node bilinear quadrilateral: shape-function gradients at the 2x2 Gauss
// points, ring volume, the mean-dilatation (B-bar) linear stiffness, and the element length
// that sets the explicit time step. Strain order (Voigt) {rr, zz, tt, rz}, with the engineering
// shear gamma_rz; hoop strain eps_tt = u_r / r (Hughes 1987, The Finite Element Method,
// Sec. 2.12; B-bar: Hughes 1980, IJNME 15:1413; Nagtegaal, Parks & Rice 1974).
// Integration weights carry 2*pi*r*detJ, so every sum is a full-ring (3-D) integral: m^3, N, J.
// Nodes are ordered counter-clockwise in the (r, z) plane (r to the right, z up).
#pragma once
#include <array>

namespace kolsky::fe {

inline constexpr int kGaussPoints = 4;
using Quad4 = std::array<double, 4>;        ///< one value per node
using Stiffness8 = std::array<double, 64>;  ///< 8x8, row-major, dofs (r0, z0, r1, z1, ...)

/// Gradients and weights of one quad in one configuration.
struct QuadGeometry {
  std::array<Quad4, kGaussPoints> dn_dr{}, dn_dz{}, n_over_r{};  ///< [gauss][node], 1/m
  Quad4 weight{};   ///< 2 pi r_g det J_g (m^3) at each Gauss point
  double volume = 0;  ///< ring volume = sum of weights (exact for the bilinear map), m^3
  Quad4 dvol_dr{}, dvol_dz{};  ///< d(volume)/d(node coordinate), m^2; the B-bar volumetric row
  bool valid = true;  ///< false when det J <= 0 at a Gauss point or r_g <= 0 (inverted element)
};

/// Gradients and weights at the 2x2 Gauss points for nodal coordinates (r, z) (m).
QuadGeometry quad_geometry(const Quad4& r, const Quad4& z);

/// Shape functions at the Gauss points, N[g][a].
const std::array<Quad4, kGaussPoints>& gauss_shape_functions();

/// Element length for the Courant limit (m): cross-section area over the longest side, the
/// shorter side of a rectangle and the smallest altitude of a parallelogram.
double courant_length(const Quad4& r, const Quad4& z);

/// Linear stiffness of the mean-dilatation element about the configuration g:
/// K = sum_g w_g B_g^T D_dev B_g + bulk * dV dV^T / V, for shear modulus G and bulk modulus K.
/// 1 zero-energy mode (axial translation) for an element off the axis: no hourglass modes.
Stiffness8 bbar_stiffness(const QuadGeometry& g, double bulk, double shear);

}  // namespace kolsky::fe
