// SHPB assembly (c): coupled FEM-DEM (Chapter 3). Meshed FE bars (and a meshed FE tube when
// specimen.tube = meshed; else the grains' rigid cylinder) around a DEM specimen, coupled
// surface by surface in coupling::FeDemShpb (coupling/fe_dem.hpp, docs/coupling.md). This
// assembly owns that model and only sequences the calls and declares the probes.
//   Probes: the names and units of the meshed-bars assembly (gauges from the FE surface strain,
//   face waves derived after the run from the first gauges by the 1-D shift), with the face
//   stresses from the summed grain contact forces on each FE face (the ring loads' axial sum /
//   specimen area), the DEM's own probes, and the off-axis fraction of the face contact
//   resultant (what the axisymmetric reduction neglects).
//   No checkpoint/restart (no FE state in ShpbState).
// The members every assembly provides are listed in shpb/assembly.hpp.
#pragma once
#include "coupling/fe_dem.hpp"
#include "shpb/experiment.hpp"
#include "shpb/probe_record.hpp"
#include "shpb/run_control.hpp"
#include "shpb/run_result.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky::shpb {

class FeDemBarsAssembly {
 public:
  /// Throws InputError (no file) for what the coupling does not support, naming the key.
  explicit FeDemBarsAssembly(const ExperimentSpec& spec);

  double stable_dt() const { return model_.stable_dt(); }
  double arrival_time() const;  ///< L_I / c_I (s)
  /// Step n in the loop's three calls (assembly.hpp): the forces of t^n, a hook with nothing
  /// to do (breakage is refused beside FE parts), the step to t^{n+1}.
  void compute_forces(long, double t, const RunControl&) { model_.forces(t); }
  time_loop::AfterForces after_forces() { return {}; }
  void advance(double dt) { model_.advance(dt); }
  void observe(double t);
  ProbeRecords probes() const;
  void finish(RunResult& r) const;
  bool can_checkpoint() const { return false; }
  [[noreturn]] void save_into(ShpbState&) const;
  void check_fits(const ShpbState&) const;
  [[noreturn]] void restore_from(const ShpbState&);

  const coupling::FeDemShpb& model() const { return model_; }

 private:
  BarSpec incident_spec_, transmission_spec_;
  bar::Pulse pulse_;
  coupling::FeDemShpb model_;
  coupling::FeDemEnergy ledger_;
};

/// The coupled model's parameters and the refusals of unsupported combinations (InputError
/// naming the key), shared with the tests.
coupling::FeDemParams fe_dem_params(const ExperimentSpec& spec);

}  // namespace kolsky::shpb
