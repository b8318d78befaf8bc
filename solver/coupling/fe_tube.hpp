// An FE tube around a DEM specimen whose end walls something else drives (the 1-D bars of
// assembly (a), shpb/one_dim_bars.hpp): the model level "1-D characteristic bars + FE tube" of
// Chapter 3 (issue 16). It is the tube half of FeDemShpb's exchange (fe_dem.hpp,
// docs/coupling.md) with a body of its own:
//   FE: fe::MeshedTube as one axisymmetric block, r in [R_s, R_s + t], centred on the
//   specimen (z in [L_s/2 - l/2, L_s/2 + l/2]), free ends, no other load.
//   Step n: drive() hands the DEM cylinder the tube wall at t^n (tube_profile); the caller
//   evaluates the grains' forces at t^n; load_and_advance() turns the cylinder's contact
//   forces, reversed, into ring loads on the wall nodes (add_contact; the circumferential and
//   lateral parts are tallied, not applied) and steps the tube to t^{n+1}. One dt for both.
//   Energy: kinetic + material work of the tube = work of the ring loads (trapezoid in force
//   over each step's displacement), which is minus the wall's work on the grains up to the
//   O(dt) lag of the wall velocity; the caller adds kinetic + material work to its ledger.
// Units SI.
#pragma once
#include <vector>

#include "core/specimen_geometry.hpp"
#include "coupling/surface_coupling.hpp"
#include "dem/dem_system.hpp"
#include "fe/body.hpp"
#include "fe/meshed_bars_tube.hpp"

namespace kolsky::coupling {

struct FeTubeParams {
  fe::MeshedTube tube;
  double specimen_length = kSpecimenLength;        ///< L_s (m): the tube is centred on it
  double specimen_radius = kSpecimenDiameter / 2;  ///< R_s (m): the tube's inner radius
  int threads = 1;
};

class FeTube {
 public:
  /// `sys` is the specimen the tube will confine: its cylinder 0 (rigid, radius R_s) and grain
  /// sizes set the node-spring limit of stable_dt(). Throws InputError (paths
  /// "specimen.tube_*", "specimen.tube").
  FeTube(const FeTubeParams& p, const dem::DemSystem& sys);

  /// min(element Courant bound, grain springs on a wall node): as FeDemShpb::stable_dt, a
  /// node of tributary area A carries at most A / (pi r_min^2) grains of the wall law's
  /// stiffest spring (raw: the caller's safety factor applies).
  double stable_dt() const;
  /// Cylinder 0 of `sys` takes the tube wall's shape at t^n (before the forces of t^n).
  void drive(dem::DemSystem& sys) const;
  /// After the forces of t^n: ring loads from cylinder 0's contacts, then t^n -> t^{n+1}.
  void load_and_advance(const dem::DemSystem& sys, double dt);

  double radial_force() const { return radial_force_; }  ///< grains on the wall, outward + (N)
  double kinetic_energy() const { return body_.kinetic_energy(); }
  double material_work() const { return body_.material_work(); }
  double surface_work() const { return surface_work_; }  ///< work of the ring loads (J)
  /// Largest lateral resultant of the wall's contact forces over the largest radial sum.
  double off_axis_fraction() const { return peak_radial_ > 0 ? peak_lateral_ / peak_radial_ : 0.0; }
  /// Ring-area mean radial displacement of the wall nodes (m).
  double mean_wall_displacement() const;
  bool finite() const { return body_.finite(); }
  const fe::Body& body() const { return body_; }

 private:
  FeTubeParams p_;
  fe::Block block_;
  fe::Body body_;
  std::vector<int> wall_;         // inner-wall nodes, ascending z
  std::vector<double> wall_area_; // tributary ring areas (m^2)
  std::vector<double> prev_fr_, prev_fz_;
  int slot_ = 0;                  // cylinder 0's wall slot in the DEM system
  double node_dt_ = 0, surface_work_ = 0, radial_force_ = 0, peak_radial_ = 0, peak_lateral_ = 0;
};

}  // namespace kolsky::coupling
