// DEM specimen between the bar faces (core/specimen_coupling.hpp): grains in a confining tube
// (CylinderWall, radius R, axis z) closed by two driven planes that follow the bar faces:
// front wall at z = intrusion_front (normal +z), back wall at z = L - intrusion_back (normal
// -z). forces() returns the walls' total normal contact forces (compression +). The planes are
// massless (face_mass() = 0): the bar faces carry the inertia. Energy: kinetic energy of the
// grains (and tube mode), and internal work = elastic energy gained since construction plus
// everything dissipated, so energy().total() changes exactly by the work the faces do.
#pragma once
#include <optional>

#include "core/specimen_coupling.hpp"
#include "core/specimen_geometry.hpp"
#include "dem/breakage_engine.hpp"
#include "dem/dem_system.hpp"
#include "dem/rest_relaxation.hpp"

namespace kolsky::dem {

struct DemSpecimenState;  // dem_state.hpp: checkpoint/restart state

/// Walls of the specimen. Defaults: the Table 4.1 linear wall contact (LinearParams{}:
/// k_n = 2.6e6 N/m, k_s = 1.6e6 N/m, friction 0.3) on both ends and the tube; a rigid tube.
struct SpecimenWalls {
  double length = kSpecimenLength;        ///< L, initial distance between the end planes, m
  double radius = kSpecimenDiameter / 2;  ///< inner radius of the confining tube, m
  WallLaw end_law = linear_spring(LinearParams{});
  WallLaw tube_law = linear_spring(LinearParams{});
  std::optional<TubeCompliance> tube_compliance;  ///< none: rigid tube
  /// Hold the grains until loaded (docs/dem.md, "Holding the specimen until the wave
  /// arrives"): while neither face has moved into the specimen by more than hold_threshold,
  /// forces() returns the wall forces of the initial state and advance() takes no DEM step.
  /// Off by default (existing scenes unchanged); the Chapter 4 scenes turn it on.
  bool hold_until_loaded = false;
  double hold_threshold = 1e-12;  ///< m, face intrusion that releases the hold
  /// Preload on the supports (docs/dem.md, "Pre-stressed specimens"): the wall forces of the
  /// initial state F0 (a pre-stressed packing's seating load) are held by the bar supports and
  /// the gauges are zeroed with it, so forces() hands the bars only the change F - F0 (linear
  /// superposition in the elastic bars). Off: the bars carry the full wall forces from t = 0.
  bool preload_on_supports = false;
};

class DemSpecimen {
 public:
  /// Grains must have their centres inside the tube and between z = 0 and z = L. Throws
  /// kolsky::InputError otherwise (or for any invalid DemSystem input).
  /// `history`: tangential histories of the grains' contacts (a preparation's end state,
  /// rest_relaxation.hpp), keyed to the walls in the order this constructor adds them (front
  /// plane, back plane, tube); empty: every contact starts without one.
  DemSpecimen(Particles particles, std::vector<Material> materials, ContactLaw law,
              const SpecimenWalls& walls, DemOptions options = {},
              const ContactHistory& history = {});

  double area() const;  ///< pi R^2, m^2
  double length() const { return walls_.length; }
  double face_mass() const { return 0.0; }
  double stable_dt() const { return sys_.stable_dt(); }
  /// Places the end walls at the face positions of t^n, completes the step in progress
  /// (forces at t^n, second half kick), returns the wall forces at t^n.
  FaceForces forces(const FaceState& faces);
  /// Starts the step t^n -> t^{n+1}: half kick with the t^n forces, drift.
  void advance(double dt);
  /// The breaks due between the forces of t^n (forces() just returned them) and the step from
  /// t^n, every check_interval steps (or check_period); returns the number of grains broken.
  /// A step is forces(), apply_due_breaks(), advance(): the caller applies the breaks (the
  /// run's after-forces hook, shpb/assembly.hpp) because a break may lower stable_dt(), and
  /// a caller whose dt follows the limit chooses the dt it hands to advance() only after it.
  /// A caller that skips it gets no breaks; one that calls it twice in a step counts the
  /// cadence twice.
  std::size_t apply_due_breaks();
  SpecimenEnergy energy() const;
  /// (intrusion_front + intrusion_back) / L of the last forces() call.
  double mean_strain() const;
  /// Elastic energy stored in the grains' contacts at construction (the packing's residual
  /// overlaps), J: energy the specimen may release without any work from the faces.
  double initial_elastic_energy() const { return elastic_0_; }
  bool finite() const { return sys_.finite(); }
  /// Whether the grains are still held (hold_until_loaded and no face has moved in yet).
  bool held() const { return held_; }
  /// forces() calls answered while held (steps skipped), and the face intrusions (m) at the
  /// release; the outward drift of a face under the packing's residual force is bounded by it.
  long held_calls() const { return held_calls_; }
  FaceState faces_at_release() const { return release_faces_; }

  const DemSystem& system() const { return sys_; }
  /// The system itself, for the FE-DEM coupling (coupling/fe_dem.hpp), which shapes the walls
  /// (DemSystem::drive_plane_profile, drive_cylinder) and steps the system without forces() /
  /// advance(); a specimen is driven one way or the other, never both.
  DemSystem& coupled_system() { return sys_; }

  /// Turns on particle breakage (Sec. 5.2.3, breakage_engine.hpp): every
  /// p.cadence.check_interval steps, between two steps, the grains that meet the criteria are
  /// replaced by their daughters. The system must have been built with
  /// DemOptions::smallest_radius_to_come covering the daughters (make_dem_specimen does).
  /// Throws InputError for bad parameters. p.cadence.check_period > 0 (s) checks instead once
  /// that much simulated time has passed since the last check: the same cadence in time
  /// whatever dt is (a run whose dt is refined after breaks starts at a step several times the
  /// up-front one; docs/breakage.md, "Checks").
  void enable_breakage(const BreakageParams& p, std::uint64_t seed);
  /// The breakage state (nullptr without breakage).
  const BreakageState* breakage() const { return breakage_ ? &*breakage_ : nullptr; }
  int front_plane() const { return front_; }
  int back_plane() const { return back_; }

  /// The preparation's relaxation to rest (make_dem_specimen with DemSpecimenParams::rest);
  /// none: the run starts from the packing as it was.
  const std::optional<RestRelaxationOutcome>& rest_relaxation() const { return rest_; }
  void set_rest_relaxation(const RestRelaxationOutcome& o) { rest_ = o; }

  /// Wall forces of the initial state (front, back), N: the preload when preload_on_supports.
  FaceForces initial_forces() const { return forces_0_; }

  /// Checkpoint and restart (dem_state.hpp; defined in dem_state.cpp); restore_state needs a
  /// specimen built from the same parameters.
  DemSpecimenState save_state() const;
  void restore_state(const DemSpecimenState& s);

 private:
  SpecimenWalls walls_;
  DemSystem sys_;
  int front_ = 0, back_ = 0;
  FaceState faces_;
  bool stepping_ = false;
  double elastic_0_ = 0;
  bool held_ = false;
  long held_calls_ = 0;
  FaceForces forces_0_;     // wall forces of the initial state (planes at 0)
  FaceState release_faces_;
  FaceState held_faces_;    // faces at the last held call
  double held_work_ = 0;    // work of the faces on the held specimen, J
  std::optional<BreakageState> breakage_;
  long steps_since_check_ = 0;
  double time_since_check_ = 0;   // s, advanced by advance(dt)
  std::optional<RestRelaxationOutcome> rest_;
};

}  // namespace kolsky::dem
