// What one specimen model adds to the 1-D bar assembly (shpb/one_dim_bars.hpp) beyond the
// bar/specimen interface of core/specimen_coupling.hpp. One overload per model, chosen at
// compile time inside the assembly's std::visit, so the generic step and sample code name no
// model and branch on none:
//   energy_stored_at_start  energy the specimen may release with no work from the faces; it
//                           joins the injected energy as the scale of the blow-up bound (a DEM
//                           packing's residual overlaps: before the pulse arrives the injected
//                           energy is still ~0, and the ledger's round-off scales with it)
//   at_forces_evaluated     called between forces() and advance() of step n: the one point of
//                           a step where positions, velocities and forces all belong to t^n,
//                           hence where DEM particle snapshots are taken (RunControl::snapshot)
//   apply_due_breaks        the assembly's after-forces hook (assembly.hpp), right after
//                           at_forces_evaluated: the grains due to break now (a DEM specimen
//                           with breakage; 0, nothing done, for the others); returns how many
//   add_model_probes        probes only this model records, appended after the bar gauges
// A new specimen model adds its four overloads here (the compiler asks for them).
#pragma once
#include <cstddef>

#include "bar/specimen_column.hpp"
#include "dem/dem_specimen.hpp"
#include "fe/fe_specimen.hpp"
#include "shpb/probe_record.hpp"
#include "shpb/run_control.hpp"

namespace kolsky::shpb {

inline double energy_stored_at_start(const bar::SpecimenColumn&) { return 0.0; }
inline double energy_stored_at_start(const fe::FeSpecimen&) { return 0.0; }
inline double energy_stored_at_start(const dem::DemSpecimen& d) { return d.initial_elastic_energy(); }

inline void at_forces_evaluated(const bar::SpecimenColumn&, long, double, const RunControl&) {}
inline void at_forces_evaluated(const fe::FeSpecimen&, long, double, const RunControl&) {}
/// Inline: this runs every step of a DEM run, and costs two tests when no snapshot is due.
inline void at_forces_evaluated(const dem::DemSpecimen& d, long n, double t, const RunControl& c) {
  if (c.snapshot_every > 0 && n % c.snapshot_every == 0) {
    if (c.snapshot) c.snapshot(n, t, d.system().particles());
    if (c.grain_size_curve && d.breakage())
      c.grain_size_curve(n, t, dem::current_grain_size_curve(*d.breakage(), d.system().particles()));
  }
}

inline std::size_t apply_due_breaks(bar::SpecimenColumn&) { return 0; }
inline std::size_t apply_due_breaks(fe::FeSpecimen&) { return 0; }
inline std::size_t apply_due_breaks(dem::DemSpecimen& d) { return d.apply_due_breaks(); }

inline void add_model_probes(const bar::SpecimenColumn&, ProbeRecords&) {}
inline void add_model_probes(const fe::FeSpecimen&, ProbeRecords&) {}
/// Grain kinetic energy, coordination numbers and contact counts. The samplers read d by
/// reference (probe_record.hpp, "Lifetime").
void add_model_probes(const dem::DemSpecimen& d, ProbeRecords& out);

/// The FE specimen's own step and energy checks as the run's time.check_stability sets them
/// (1-D and meshed bars alike): false lifts both, as it lifts the loop's.
inline fe::FeSpecimenParams with_checks(fe::FeSpecimenParams p, bool check_stability) {
  p.check_dt = p.check_energy = check_stability;
  return p;
}

}  // namespace kolsky::shpb
