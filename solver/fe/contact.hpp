// Node-to-surface penalty contact with Coulomb friction (the specimen's nodes are the slaves).
//   normal:      f_n = max(0, k g + c dg/dt) for a penetration g > 0, else 0 (no adhesion);
//                c = 2 zeta sqrt(k m) damps the node-on-spring chatter that penalty contact
//                otherwise pumps energy into under central differences (LS-DYNA's VDC; the
//                gap rate uses the half-step velocities v^{n-1/2}, the face rate likewise)
//   tangential:  an elastic stick spring of the same stiffness k driven by the slip increment
//                since the last call, capped at mu f_n (return mapping; Wriggers 2006,
//                Computational Contact Mechanics, Sec. 5.2). mu = 0 gives f_t = 0 exactly.
// Surfaces: a rigid plane normal to z (a bar face), a rigid cylinder r = R (rigid tube, or one
// backed by a radial spring), and a polyline through deformable master nodes (meshed tube,
// meshed bar face).
// Energy: normal_work and friction_work accumulate the work the contact forces take from the
// relative motion of the two sides (trapezoid in force over each step's relative displacement,
// the pairing central differences conserve): spring energy plus what the dampers and Coulomb
// sliding dissipated. normal_energy() is the springs' present share, k g^2 / 2. Units: N, m, J.
#pragma once
#include <array>
#include <vector>

#include "fe/mesh.hpp"

namespace kolsky::fe {

/// The contact between one set of specimen nodes and one surface, with its history.
struct ContactSet {
  double friction = 0.0;                 ///< Coulomb mu
  std::vector<int> node;                 ///< slave nodes
  std::vector<double> stiffness;         ///< penalty stiffness per slave node (N/m)
  std::vector<double> damping;           ///< normal damping per slave node (N s/m)
  std::vector<double> normal_force;      ///< f_n at t^n (N, >= 0), spring + damper
  std::vector<double> tangential_force;  ///< f_t at t^n on the slave, along +r (planes) or +z (N)
  std::vector<double> penetration;       ///< g at t^n (m, > 0 when penetrating)
  std::vector<int> segment;              ///< master segment per slave (polyline only), -1 = none
  double surface_position = 0.0;         ///< plane z at the last call (planes only), m
  double normal_work = 0.0;              ///< J, cumulative
  double friction_work = 0.0;            ///< J, cumulative

  /// Sizes the per-node arrays for the nodes and stiffnesses already filled in.
  void reset_history();
  double normal_energy() const;    ///< spring energy sum k g^2 / 2, J
  double max_penetration() const;  ///< m
  double total_normal() const;     ///< sum f_n, N
  double total_shear() const;      ///< sum |f_t|, N
};

/// Rigid plane z = z_plane moving at v_plane (+z), the specimen on the side `side` (+1:
/// z > z_plane, front face; -1: z < z_plane, back face). Adds the forces to nodes.f*_ext;
/// returns sum f_n (N).
double contact_plane(ContactSet& c, Nodes& nodes, double z_plane, double v_plane, int side);
/// Rigid cylinder r = radius around the specimen (slaves inside). Adds to nodes.f*_ext.
void contact_cylinder(ContactSet& c, Nodes& nodes, double radius);
/// Deformable surface: the polyline through `master` nodes, ascending along the axis normal to
/// `normal_direction` (0: normal r, polyline along z, e.g. a tube's inner nodes; 1: normal z,
/// polyline along r, e.g. a meshed bar's end face). `side`: where the master lies relative to
/// the slaves along the normal, -1 master at larger coordinate (tube outside the specimen),
/// +1 master at smaller coordinate (a bar face below the specimen's front face). The normal is
/// taken along the axis (a tube wall or a bar face stays nearly straight). Reactions go to the
/// two master nodes by their linear weights.
void contact_polyline(ContactSet& c, Nodes& nodes, const std::vector<int>& master,
                      int normal_direction = 0, int side = -1);

/// A linear spring on up to 3 degrees of freedom (2 * node + {0: r, 1: z}): energy
/// k (sum_j w_j x_j)^2 / 2. The linearised penalty contact, for time-step estimates.
struct SpringStencil {
  std::array<int, 3> dof{-1, -1, -1};
  std::array<double, 3> weight{0, 0, 0};
  double k = 0.0;
};

/// Every spring the contact set could form at the current geometry (normal, and tangential
/// when mu > 0); polyline slaves are paired with the segment at their current position along
/// the tangential axis (1 - normal_direction).
/// abs_weights: put |N| <= 1 bounds (1) on the master weights, for a Gershgorin bound that holds
/// as the slaves slide along the masters.
void contact_springs(const ContactSet& c, const Nodes& nodes, const std::vector<int>* master,
                     int normal_direction, bool abs_weights, std::vector<SpringStencil>& out);

}  // namespace kolsky::fe
