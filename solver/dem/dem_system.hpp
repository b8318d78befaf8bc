// A DEM assembly as a facade over its components (issue 32; docs/architecture.md draws them):
// particles (particles.hpp), the contact network (contact_network.hpp), the energy ledger
// (energy_ledger.hpp), the walls (wall.hpp: planes and cylinders, one concept), the grain law
// (contact_law.hpp) and the step executor (time/step_executor.hpp: the thread count). It keeps
// what ties them together (options, time, the step in progress, skin, stable dt) and steps
// them: velocity Verlet (kick-drift-kick; dashpots see mid-step velocities, as in LIGGGHTS),
// then rotational retardation w <- k w, Eqs. 4.12-4.14 (integrator.hpp), with one force
// evaluation between (contact_forces.hpp). Each contact is computed once and gathered per
// particle in a fixed order, so results are bitwise the same for any OpenMP thread count.
// Stable dt = min(Rayleigh step of the smallest grain, sqrt(m/k) of the stiffest linear
// contact, tube ring mode); the stepping loop applies its safety factor. Details: docs/dem.md.
#pragma once
#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "dem/contact_history.hpp"
#include "dem/contact_law.hpp"
#include "dem/contact_network.hpp"
#include "dem/energy_ledger.hpp"
#include "dem/integrator.hpp"
#include "dem/neighbour_list.hpp"
#include "dem/particle_edit.hpp"
#include "dem/particles.hpp"
#include "dem/wall.hpp"
#include "dem/walls.hpp"
#include "time/step_executor.hpp"

namespace kolsky::dem {

struct DemState;  // dem_state.hpp: checkpoint/restart state

struct DemOptions {
  double skin_over_min_radius = 0.5;  ///< Verlet skin as a multiple of the smallest radius
  RollingRetardation rolling;
  /// Hertz-Mindlin grain pairs through the batched, branch-free kernel
  /// (hertz_mindlin_batch.hpp; bitwise the same results). false: the per-contact kernel, kept
  /// as the reference the tests compare against.
  bool batched_hertz_mindlin = true;
  /// The grain-pair sweep runs over fixed blocks of this many owner grains (threads take whole
  /// blocks): a pair whose partner lies in the owner's block adds the partner's side to it
  /// directly, in pair order, instead of through a 64-byte slot that gather() reads back.
  /// Results depend on it (the order of each grain's sums), never on the thread count.
  /// Spatially sorted grains have most partners within a few thousand indices (docs/dem.md,
  /// "Performance"). Must be > 0.
  int owner_block = 2048;
  /// After an edit (DemSystem::edit), when the grains added since the last spatial sort exceed
  /// this fraction of all grains, the system re-sorts them (Morton order of cells of the
  /// smallest diameter, spatial_sort.hpp) and starts fresh owner blocks: fragments appended at the
  /// end of the arrays lose the locality the sweep relies on (docs/dem.md, "Performance").
  /// A re-sort changes each grain's summation order (results move by round-off, not physics).
  /// 0: never. Without edits it never fires.
  double resort_added_fraction = 0.1;
  /// Smallest grain radius a run may create (m; breakage daughters, Sec. 5.2.3): stable_dt()
  /// covers a grain of this radius of every material from the start, so the step fixed when
  /// the run is planned stays stable as grains break (docs/breakage.md). 0: the grains present.
  double smallest_radius_to_come = 0.0;
  /// step() (begin_step, finish_step) runs through an executor (time/step_executor.hpp) that
  /// chooses between one thread and the caller's OpenMP count from the step rate it measures
  /// (time/thread_governor.hpp): two threads beside a busy core are slower than one under any
  /// wait policy. Results do not depend on it (they are bitwise the same for any thread
  /// count); false: always the caller's count (benchmarks that measure a fixed count).
  bool adapt_threads = true;
  /// Window, probe interval and margin of that choice (time/thread_governor.hpp).
  time_loop::ThreadGovernorOptions governor;
};

/// The fraction of stable_dt() at which kolsky's own DEM loops step (packing, pre-stress,
/// tests): 0.3 of the Rayleigh step, the upper end of the fractions in common DEM use, since a
/// grain with several contacts has a shorter critical step than one contact gives (O'Sullivan
/// and Bray 2004). It is the fraction kolsky has always stepped at, so packings and results
/// keep their bits. A scene run applies time.safety_factor instead (0.5 x this by default for
/// a DEM specimen).
inline constexpr double kDemStepFraction = 0.3;

class DemSystem {
 public:
  /// Precondition: `law` was built for `materials`. Throws kolsky::InputError on bad input.
  DemSystem(Particles particles, std::vector<Material> materials, ContactLaw law,
            DemOptions options = {});

  /// Adds a wall; returns its index among the planes (cylinders). Resets wall-contact history.
  int add_plane(const PlaneWall& w);
  int add_cylinder(const CylinderWall& w);
  /// Sets a DrivenPlane's offset along its normal (m) and speed (m/s) for the coming force
  /// evaluation.
  void drive_plane(int plane, double offset, double speed);

  /// Gives DrivenPlane k a deformed shape for the coming force evaluation (walls.hpp,
  /// WallProfile; stations: distance from the z axis, so the plane's normal must be +-z):
  /// a grain at distance rho from the axis meets the plane shifted by profile.at(rho).offset
  /// along its normal, moving at that station's speeds. The plane's scalar offset and speed
  /// are then unused, and its work on the grains is left out of DemEnergy::wall_work (the
  /// caller that deforms it books the interface work; docs/coupling.md). Throws InputError.
  void drive_plane_profile(int plane, WallProfile profile);
  /// Gives rigid cylinder k (no compliance) a deformed shape: stations z, offset the outward
  /// radial displacement of the surface at that z (radius + offset), normal_speed its rate,
  /// tangential_speed the surface's axial velocity. Throws InputError.
  void drive_cylinder(int cylinder, WallProfile profile);
  /// Calls f(i, force on grain i) for every touching contact of wall `slot` (WallSlots) of the
  /// last force evaluation, in candidate (particle) order: the contact forces a deformable
  /// wall's owner maps back onto its surface (the wall feels minus them).
  template <class F> void for_each_wall_force(int slot, F&& f) const {
    if (forces_valid_) dem::for_each_wall_force(net_, slot, f);
  }

  /// Largest dt step() accepts (s): the raw limit, min over the Rayleigh step of the smallest
  /// grain, sqrt(m/k) of the stiffest linear contact and the tube ring mode, with no safety
  /// factor in it. The loop that steps the system applies its own fraction once (the scene's
  /// time.safety_factor; kDemStepFraction in kolsky's own DEM loops).
  double stable_dt() const;
  /// One step of size dt (s): begin_step(dt) then finish_step(). Throws kolsky::InputError
  /// ("dem.dt") if dt <= 0, kolsky::NumericalError if dt > stable_dt() (the limit fell).
  void step(double dt);
  /// First half: half kick with the current forces, drift, prescribed walls move.
  void begin_step(double dt);
  /// Second half: (neighbour rebuild if needed), forces at the new positions, half kick,
  /// rotational retardation.
  void finish_step();
  /// Evaluates the forces of the current state without advancing (no history increment).
  void compute_forces() { compute_forces(0.0); }

  const Particles& particles() const { return p_; }
  /// Write access (velocities, positions, even radii or added particles): the next step or
  /// force evaluation revalidates, rederives skin and stable dt, and rebuilds the lists.
  /// Changing the count this way drops every contact history; edit() keeps them.
  Particles& mutable_particles();
  /// Removes and adds grains between two steps (particle_edit.hpp), carrying what survives: the
  /// tangential histories of pairs and wall contacts whose grains both remain, every
  /// per-particle array, the forces, and the owner-block partition (each surviving grain
  /// stays in its block, so its sums keep their order). A grain removed with touching
  /// contacts, or added overlapping something, makes the forces be evaluated again at once
  /// (as a first step would: history unchanged, no time advance); an edit that touches no
  /// contact leaves the following steps bitwise those of a run without it. Energy moved by
  /// the edit goes to DemEnergy::edited. Returns where every grain went (a locality re-sort,
  /// DemOptions::resort_added_fraction, is included in the map). Throws
  /// kolsky::InputError ("dem.edit...") for a bad index or particle, std::logic_error
  /// between begin_step() and finish_step().
  EditMap edit(const ParticleEdit& e);
  /// Owner blocks as index ranges [block_first()[b], block_first()[b+1]) (DemOptions::owner_block).
  const std::vector<int>& block_first() const { return net_.block_first; }
  /// How many locality re-sorts (DemOptions::resort_added_fraction) edits have triggered.
  std::size_t n_resorts() const { return n_resorts_; }
  /// Sets every grain's velocity and spin (and a compliant tube's radial speed) to zero
  /// between two steps, keeping the forces and lists (velocities enter neither the list nor
  /// the elastic forces): the kinetic damping of rest_relaxation.hpp.
  void stop_grains() {
    std::fill(p_.v.begin(), p_.v.end(), Vec3{});
    std::fill(p_.omega.begin(), p_.omega.end(), Vec3{});
    for (Wall& w : walls_) stop(w);
  }
  const std::vector<Material>& materials() const { return materials_; }
  double time() const { return time_; }

  /// Every wall, in slot order (WallSlots: planes first, then cylinders); wall.hpp asks each
  /// its gap, normal and velocity at a point.
  const std::vector<Wall>& walls() const { return walls_; }
  WallSlots wall_slots() const { return {n_planes_, static_cast<int>(walls_.size()) - n_planes_}; }
  int n_planes() const { return n_planes_; }
  int n_cylinders() const { return static_cast<int>(walls_.size()) - n_planes_; }
  const PlaneWall& plane(int k) const { return plane_at(k).wall; }
  double plane_offset(int k) const { return plane_at(k).offset; }
  double plane_speed(int k) const { return plane_at(k).speed; }
  /// Total normal contact force between plane k and the particles (compression +, N).
  double plane_force(int k) const { return walls_[wall_slots().slot(WallKind::plane, k)].force; }
  const CylinderWall& cylinder(int k) const { return cylinder_at(k).wall; }
  /// Total outward radial contact force on cylinder k (N) and its radial displacement (m).
  double cylinder_force(int k) const { return walls_[wall_slots().slot(WallKind::cylinder, k)].force; }
  double cylinder_displacement(int k) const { return cylinder_at(k).u; }

  /// The energy ledger's reading (energy_ledger.hpp).
  DemEnergy energy() const { return dem::energy(ledger_, p_, net_, walls_); }
  /// Every touching contact of the last force evaluation, pairs first (in pair order), then
  /// wall contacts (in slot, particle order): contact_network.hpp, for_each_touching_contact
  /// (the elastic normal force it passes for a wall is the wall law's spring without its
  /// dashpot, as a grain pair's Hertz force). Nothing between an edit or restore and the next
  /// evaluation.
  template <class Pair, class OnWall> void for_each_touching_contact(Pair&& pair, OnWall&& wall) const {
    if (forces_valid_) dem::for_each_touching_contact(net_, p_, walls_, pair, wall);
  }
  /// The contact network (contact_network.hpp): lists, owner blocks, histories, outputs.
  const ContactNetwork& network() const { return net_; }
  std::size_t n_pairs() const { return net_.pairs.size(); }
  std::size_t n_contacts() const { return n_touching_pairs(net_); }              ///< touching grain pairs
  std::size_t n_wall_contacts() const { return n_touching_wall_contacts(net_); }  ///< touching grain-wall contacts
  std::size_t n_rebuilds() const { return net_.n_rebuilds; }
  /// The thread-count choice of step() (DemOptions::adapt_threads): probes and switches.
  const time_loop::ThreadGovernor& thread_governor() const { return exec_.governor(); }
  double skin() const { return skin_; }
  bool finite() const;

  /// Checkpoint and restart (dem_state.hpp; defined in dem_state.cpp). restore_state needs a
  /// system built with the same materials, law and walls; the particles (their count too, after
  /// edits) and the owner blocks come from the state. It throws kolsky::InputError
  /// ("dem.state") when the walls disagree. The continued run is bitwise the uninterrupted one.
  DemState save_state() const;
  void restore_state(const DemState& s);
  /// The tangential histories of the last force evaluation's contacts (dem_state.cpp).
  ContactHistory contact_history() const;
  /// Gives the contacts of the current particles these histories (a preparation's final
  /// state handed to the run; contact_history.hpp): the next force evaluation rebuilds the
  /// lists and attaches each history by key, as after restore_state. Call it after the walls
  /// are added (their slots key the wall histories). Throws kolsky::InputError ("dem.state")
  /// for histories that name no particle or wall of the system, std::logic_error inside a step.
  void seed_contact_history(const ContactHistory& h);

 private:
  Wall& wall_of(WallKind kind, int k);  // drive_*: checked
  const Plane& plane_at(int k) const { return std::get<Plane>(walls_[wall_slots().slot(WallKind::plane, k)].shape); }
  const Cylinder& cylinder_at(int k) const {
    return std::get<Cylinder>(walls_[wall_slots().slot(WallKind::cylinder, k)].shape);
  }
  // Lists rebuilt if needed, then evaluate_contacts (contact_forces.hpp).
  void compute_forces(double dt);
  void kick_drift(double half_dt, double dt);   // begin_step: half kick, then drift
  void kick_retard(double half_dt, double dt);  // finish_step: half kick, then retardation
  void rebuild();  // the network's, then the walls marked built
  void check_dt(double dt) const;
  double compute_stable_dt() const;
  void refresh_after_edit();

  Particles p_;
  std::vector<Material> materials_;
  ContactLaw law_;
  DemOptions opt_;
  double skin_ = 0, time_ = 0, pending_dt_ = 0, stable_dt_ = 0;
  bool forces_valid_ = false, particles_changed_ = false;
  // The thread count of step(): chosen from the measured wall time of begin_step's and
  // finish_step's work (opt_.adapt_threads).
  time_loop::StepExecutor exec_;

  // By slot (WallSlots): planes first, so that every loop over walls keeps the order the
  // force sums have always had (planes, then cylinders).
  std::vector<Wall> walls_;
  int n_planes_ = 0;

  ContactNetwork net_;
  EnergyLedger ledger_;
  std::size_t added_since_sort_ = 0, n_resorts_ = 0;
};

}  // namespace kolsky::dem
