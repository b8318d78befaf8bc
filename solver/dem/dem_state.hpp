// Plain-struct state of a DemSystem / DemSpecimen for checkpoint and restart (no io here: the
// io module writes and reads these structs; physics modules never include io).
//
// What is stored: everything the kick-drift-kick step reads (particle arrays including the
// forces and torques of the last evaluation, per-particle dissipated energy, time, the step in
// progress), the tangential histories of pair and wall contacts keyed by (i, j) and by
// (wall slot, particle), and the walls' dynamic state. What is not stored: the Verlet pair list
// and the wall-candidate lists. restore_state() invalidates them, so the next force evaluation
// rebuilds them from the restored positions and re-attaches the histories by key (the same
// carry as an ordinary rebuild). The rebuild timing differs from the uninterrupted run, but it
// cannot change a result: only touching pairs produce forces, every list contains all of them,
// and all sums run over touching contacts in (owner, partner) / (wall, particle) order, which
// no list composition changes. verification/test_dem_restart.cpp checks bitwise agreement.
// Consequence: between restore_state() and the next force evaluation, the per-contact outputs
// (energy().elastic's contact part, n_contacts(), n_wall_contacts()) read zero.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/specimen_coupling.hpp"
#include "dem/contact_network.hpp"
#include "dem/energy_ledger.hpp"
#include "dem/particles.hpp"
#include "dem/vec3.hpp"

namespace kolsky::dem {

/// Each component's fields are its own: the contact network's (tangential histories of pair
/// and wall contacts by key, owner blocks, rebuild count) are the ContactNetworkState part
/// (contact_network.hpp, save_network / restore_network), the energy ledger's (per-grain
/// dissipation, what removed grains dissipated, what edits took out) the EnergyLedger part.
struct DemState : ContactNetworkState, EnergyLedger {
  Particles particles;              ///< every field: x, v, omega, f, torque, radius, mass, ...
  double time = 0;                  ///< s
  double pending_dt = 0;            ///< > 0: begin_step done, finish_step pending (s)
  bool forces_valid = false;        ///< particles.f/torque hold the current state's forces
  std::size_t added_since_sort = 0; ///< grains edits added since the last locality sort

  struct Plane {
    double offset = 0, speed = 0, force = 0, offset_at_force = 0, work = 0;
  };
  struct Tube {
    double u = 0, u_dot = 0, force = 0;
  };
  std::vector<Plane> planes;
  std::vector<Tube> tubes;
};

/// What breakage adds to a specimen's state (breakage_engine.hpp): the per-grain arrays, the
/// ledger and the check counter. The parameters, seed, d50 and initial curve are not stored:
/// the specimen a run restores into is rebuilt from the same scene and has them.
struct DemBreakageState {
  std::vector<std::uint64_t> id;
  std::vector<double> strength;
  std::vector<int> generation;
  std::uint64_t n_primary = 0, n_secondary = 0;
  double lost_volume = 0;
  std::vector<double> fines_volume, fines_d_min, fines_d_max, fines_alpha;
  double kinetic_removed = 0, insertion_energy = 0;
  long steps_since_check = 0;
  double time_since_check = 0;  ///< s, for a check period in time (check_period > 0)
};

/// DemSpecimen = DemSystem + the last face state, whether a step is in progress, and the
/// elastic energy at construction (the reference of energy().internal_work).
struct DemSpecimenState {
  DemState system;
  FaceState faces;
  bool stepping = false;
  double elastic_0 = 0;
  bool held = false;  ///< SpecimenWalls::hold_until_loaded still holding
  double held_work = 0;  ///< work of the faces on the held specimen, J
  std::optional<DemBreakageState> breakage;  ///< none: a specimen without breakage
};

}  // namespace kolsky::dem
