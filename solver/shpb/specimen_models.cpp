#include "shpb/specimen_models.hpp"

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
}

}  // namespace kolsky::shpb
