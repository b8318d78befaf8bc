// SHPB assembly (a): 1-D incident and transmission bars (exact characteristic bars, or the
// sphere chains of Sec. 4.3) with a specimen model between them (1-D column, FeSpecimen or
// DemSpecimen), coupled through the two face degrees of freedom the bars own
// (core/specimen_coupling.hpp: face intrusions and rates in, face forces out).
//   Step n (t^n -> t^{n+1}): the specimen takes the faces at t^n and returns the face forces at
//   t^n, breaks the grains due (a DEM specimen with breakage), then advances its interior; each bar steps under its face force; the face waves of
//   t^n update the wave energies (Eqs. 2.11-2.13, trapezoid in time) and the energy the
//   applied pulse injected (the scale of the blow-up bound).
//   Energy ledger (observe, at each output step): each bar reports the energy it delivered to
//   its face; the specimen and the face masses hold it. Their difference is the balance error;
//   growth beyond energy_tolerance * (injected + stored at start) is a blow-up (NumericalError).
//   Probes: the face waves are exact (the bars' characteristic split at the face); gauges are
//   the bars' stress at the gauge positions as strain, compression negative as measured.
//   An FE tube (specimen.tube = meshed around a dem specimen, characteristic bars only): the
//   model level "1-D bars + FE tube" of Chapter 3. coupling::FeTube gives the grains'
//   cylinder the tube wall's shape before the specimen's forces of t^n and steps the tube
//   under their ring loads before the specimen advances; its kinetic energy and material work
//   join the energy held (the wall's work on the grains and the loads' work on the tube cancel).
//   Checkpoint/restart: bars, specimen, face forces and the wave-energy accumulators; not for
//   the fe specimen or an FE tube, which have no checkpoint state.
// The members every assembly provides are listed in shpb/assembly.hpp.
#pragma once
#include <optional>
#include <variant>

#include "bar/characteristic_bar.hpp"
#include "bar/specimen_column.hpp"
#include "bar/sphere_chain.hpp"
#include "coupling/fe_tube.hpp"
#include "dem/dem_specimen.hpp"
#include "dem/dem_state.hpp"
#include "fe/fe_specimen.hpp"
#include "shpb/experiment.hpp"
#include "shpb/probe_record.hpp"
#include "shpb/run_control.hpp"
#include "shpb/run_result.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky::shpb {

using Bar = std::variant<bar::CharacteristicBar, bar::SphereChainBar>;
using Specimen = std::variant<bar::SpecimenColumn, fe::FeSpecimen, dem::DemSpecimen>;

/// Checkpoint states, in the order of the variants above (the fe specimen has none).
using BarState = std::variant<bar::CharacteristicBar::State, bar::SphereChainBar::State>;
using SpecimenState = std::variant<bar::SpecimenColumn::State, dem::DemSpecimenState>;

class OneDimBarsAssembly {
 public:
  /// spec.bar_kind is characteristic or sphere_chain. Builds (and, for DEM, packs) the specimen
  /// first: its face mass goes onto the bar faces.
  explicit OneDimBarsAssembly(const ExperimentSpec& spec);

  double stable_dt() const;     ///< min over the specimen and both bars (s)
  double arrival_time() const;  ///< incident wave at the specimen face (s)
  /// Step n from t = t^n in the loop's three calls (assembly.hpp). compute_forces: the
  /// specimen's face forces at t^n; control supplies the DEM snapshot hook
  /// (specimen_models.hpp). after_forces: the specimen's due breaks (a DEM specimen with
  /// breakage), never a re-plan. advance: the FE tube, the specimen and the bars to t^{n+1}.
  void compute_forces(long n, double t, const RunControl& control);
  time_loop::AfterForces after_forces();
  void advance(double dt);
  /// At an output step: checks finiteness and the energy ledger (throws NumericalError) and
  /// keeps the ledger for the energy_held / energy_delivered probes.
  void observe(double t);
  ProbeRecords probes() const;  ///< samplers read *this (probe_record.hpp, "Lifetime")
  void finish(RunResult&) const {}  ///< the face waves are already exact
  bool can_checkpoint() const { return !std::holds_alternative<fe::FeSpecimen>(specimen_) && !tube_; }
  void save_into(ShpbState& s) const;  ///< bars, specimen, forces, accumulators
  /// Throws InputError("", "restart", ...) when s was written for other bars or another
  /// specimen model; restore_from needs a state that passed it.
  void check_fits(const ShpbState& s) const;
  void restore_from(const ShpbState& s);

  const Specimen& specimen() const { return specimen_; }
  const Bar& incident_bar() const { return incident_; }
  const Bar& transmission_bar() const { return transmission_; }

 private:
  BarSpec incident_spec_, transmission_spec_;  // materials, gauges (the spec's, copied)
  BarKind kind_;
  bar::Pulse pulse_;
  double energy_tolerance_;
  bool check_stability_;  // time.check_stability: the energy check is on
  Specimen specimen_;
  Bar incident_, transmission_;
  std::optional<coupling::FeTube> tube_;  // specimen.tube = meshed (dem specimen)
  FaceForces forces_;
  double t_ = 0;                        // t^n of the step in progress (compute_forces)
  double w_i_ = 0, w_r_ = 0, w_t_ = 0;  // Eqs. 2.11-2.13 from the face waves
  double prev_[3] = {0, 0, 0};          // s_i, s_r, s_t at the previous step
  double injected_ = 0;                 // A/(rho c) * integral sigma_app^2 dt
  double held_ = 0, delivered_ = 0;     // energy ledger at the last observe()
};

}  // namespace kolsky::shpb
