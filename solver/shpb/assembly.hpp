// SHPB assemblies: what the simulated test steps between the bars' far ends, one alternative
// per way of modelling the bars and the specimen, chosen once from the ExperimentSpec
// (make_assembly) and owned by SimulatedShpb. Each alternative builds and steps only what it
// models, and declares its own probes (probe_record.hpp).
//
//   (a) OneDimBarsAssembly  1-D bars (characteristic | sphere chain) + specimen model
//                           (1-D column | FeSpecimen | DemSpecimen), coupled through the face
//                           DOFs of core/specimen_coupling.hpp (4 scalars in, 2 out)
//   (b) MeshedBarsAssembly  meshed FE bars + FE specimen (+ tube) as one FE body (fe::MeshedShpb)
//   (c) FeDemBarsAssembly   meshed FE bars (+ FE tube) + DEM specimen, coupled surface by
//                           surface (coupling/fe_dem.hpp): see "Seam (c)" below
//   (d) StrainRateWallsAssembly  no bars: a DEM specimen between a wall driven by a tabulated
//                           strain rate and a fixed wall (Sec. 5.2.1, methodology 1), through
//                           the same face interface; chosen by spec.strain_rate
//
// Every alternative provides (SimulatedShpb visits the variant once per run and runs the
// loop on the concrete type, so the per-step path has no dispatch of its own):
//   explicit A(const ExperimentSpec&)      builds what it steps; throws InputError (no path)
//   double stable_dt() const               s
//   double arrival_time() const            incident wave at the specimen face, s (0 for (d))
//   step n, t^n -> t^{n+1}, in three calls the loop makes in this order:
//   void compute_forces(long n, double t, const RunControl&)   state and forces of t^n; the
//                                          run's hooks of t^n (snapshots, grain-size curves)
//   time_loop::AfterForces after_forces()  the one point between the forces of t^n and the
//                                          step from t^n: breakage applies the due breaks
//                                          here, and asks for replan_dt when the limit may
//                                          have fallen and its dt may follow it; {} (a no-op)
//                                          for an assembly with nothing to do there
//   void advance(double dt)                t^n -> t^{n+1} with the dt the loop chose after it
//   void observe(double t)                 output step: checks, throws NumericalError
//   ProbeRecords probes() const            named records; samplers read *this
//   void finish(RunResult&) const          after the loop (also after a blow-up)
//   bool can_checkpoint() const; save_into / check_fits / restore_from (ShpbState)
//
// Seam (c), coupled FEM-DEM (Chapter 3: DEM grains in an FE tube between FE bars). It joins
// ShpbAssembly as a third alternative with the members above, and make_assembly picks it for
// bars.kind = meshed with specimen.model = dem. The face interface of core/specimen_coupling.hpp cannot carry it: the
// grains touch the meshed bar faces and the tube wall node by node, none of them plane or
// rigid. Each step hands the DEM the positions and velocities at t^n of the FE nodes on those
// surfaces, and hands the FE the nodal forces at t^n of the grain contacts on them, before
// either advances (both integrators are central differences on the same t^n). That exchange
// belongs in solver/coupling/ (surface_coupling.hpp has its data), the one layer above the
// physics modules where fe and dem may meet; the physics modules still never include each
// other, and this assembly only sequences the calls and declares the probes. Checkpointing it
// needs FE state, which ShpbState does not carry yet.
#pragma once
#include <variant>

#include "shpb/experiment.hpp"
#include "shpb/fe_dem_bars.hpp"
#include "shpb/meshed_bars.hpp"
#include "shpb/one_dim_bars.hpp"
#include "shpb/strain_rate_walls.hpp"

namespace kolsky::shpb {

using ShpbAssembly =
    std::variant<OneDimBarsAssembly, MeshedBarsAssembly, StrainRateWallsAssembly, FeDemBarsAssembly>;

/// The alternative spec.strain_rate, spec.bar_kind and spec.specimen ask for, built in place
/// (no copy of the bodies). Throws InputError (no file; paths "bars.kind", "fe.*",
/// "specimen.*", ...).
inline ShpbAssembly make_assembly(const ExperimentSpec& spec) {
  if (spec.strain_rate) return ShpbAssembly(std::in_place_type<StrainRateWallsAssembly>, spec);
  if (spec.bar_kind == BarKind::meshed && std::holds_alternative<dem::DemSpecimenParams>(spec.specimen))
    return ShpbAssembly(std::in_place_type<FeDemBarsAssembly>, spec);
  if (spec.bar_kind == BarKind::meshed) return ShpbAssembly(std::in_place_type<MeshedBarsAssembly>, spec);
  return ShpbAssembly(std::in_place_type<OneDimBarsAssembly>, spec);
}

}  // namespace kolsky::shpb
