#include "shpb/specimen_models.hpp"

#include <memory>

namespace kolsky::shpb {

void add_model_probes(const dem::DemSpecimen& d, ProbeRecords& out) {
  // Contact counts cost a pass over the contact flags (a byte count): sampled at the probe
  // cadence only, each probe counting for itself.
  const dem::DemSystem* sys = &d.system();
  auto grains = [sys] { return static_cast<double>(sys->particles().size()); };
  auto pairs = [sys] { return static_cast<double>(sys->n_contacts()); };
  auto walls = [sys] { return static_cast<double>(sys->n_wall_contacts()); };
  out.push_back({"grain_kinetic_energy", "J", "kinetic energy of the grains (translation + rotation)",
                 [sys](double) { return sys->particles().kinetic_energy(); }});
  out.push_back({"coordination_number", "1", "2 x touching grain pairs / grains",
                 [=](double) { return 2.0 * pairs() / grains(); }});
  out.push_back({"coordination_with_walls", "1", "(2 x touching grain pairs + grain-wall contacts) / grains",
                 [=](double) { return (2.0 * pairs() + walls()) / grains(); }});
  out.push_back({"grain_contacts", "1", "touching grain pairs", [=](double) { return pairs(); }});
  out.push_back({"wall_contacts", "1", "touching grain-wall contacts (end planes and tube)",
                 [=](double) { return walls(); }});
  if (sys->n_cylinders() == 1 && sys->cylinder(0).compliance) {  // specimen.tube = spring
    out.push_back({"tube_force", "N", "radial force of the grains on the compliant tube",
                   [sys](double) { return sys->cylinder_force(0); }});
    out.push_back({"tube_wall_displacement", "m", "radial displacement of the compliant tube's wall (its one radial mode)",
                   [sys](double) { return sys->cylinder_displacement(0); }});
  }
  if (d.breakage() == nullptr) return;  // the probes of a specimen without breakage stay as they were
  const dem::DemSpecimen* s = &d;
  auto ledger = [s]() -> const dem::BreakageLedger& { return s->breakage()->ledger; };
  out.push_back({"grain_count", "1", "grains in the simulation (each break: -1 + 14)", [=](double) { return grains(); }});
  out.push_back({"broken_primary", "1", "grains of the initial specimen broken (Sec. 5.3.2)",
                 [=](double) { return static_cast<double>(ledger().n_primary); }});
  out.push_back({"broken_secondary", "1", "daughters broken again (secondary breakage, Sec. 5.3.2)",
                 [=](double) { return static_cast<double>(ledger().n_secondary); }});
  out.push_back({"lost_volume", "m^3", "solid volume removed as fines (46.6 % of each parent, Table 5.3)",
                 [=](double) { return ledger().lost_volume; }});
  out.push_back({"relative_breakage", "1", "Hardin's B_r of grains + fines against the initial grains (75 um x N, Sec. 5.3.1)",
                 [s, sys](double) { return dem::relative_breakage(*s->breakage(), sys->particles()); }});
  // One more pass over the contacts per output step (not per check), shared by the two probes
  // through the output time they are sampled at: a diagnostic only.
  if (s->breakage()->params.coordination_limit > 0) {
    struct Held {
      double t = -1.0;
      dem::HeldByCoordination held;
    };
    auto last = std::make_shared<Held>();
    auto held = [s, sys, last](double t) -> const dem::HeldByCoordination& {
      if (t != last->t) *last = {t, dem::held_by_coordination(*sys, *s->breakage())};
      return last->held;
    };
    out.push_back({"primary_held_by_coordination", "1",
                   "initial grains at or past their force criterion kept whole by c_lim (coordination >= c_lim)",
                   [=](double t) { return static_cast<double>(held(t).primary); }});
    out.push_back({"primary_held_at_limit", "1", "of those, the grains with exactly c_lim contacts",
                   [=](double t) { return static_cast<double>(held(t).primary_at_limit); }});
  }
  out.push_back({"breakage_kinetic_removed", "J", "kinetic energy that left with the lost mass",
                 [s](double) { return s->breakage()->kinetic_removed; }});
  out.push_back({"breakage_insertion_energy", "J", "change of contact energy when daughters replace parents",
                 [s](double) { return s->breakage()->insertion_energy; }});
}

}  // namespace kolsky::shpb
