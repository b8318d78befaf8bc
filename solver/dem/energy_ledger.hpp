// The energy ledger of a DEM assembly (docs/dem.md, "Energy ledger"), a value type beside the
// particles, the contact network and the walls (issue 32): the energy each grain dissipated
// (booked by the contact kernels and the rolling retardation at every step), what the grains
// edits removed had dissipated, and the energy edits took out. Its reading, energy(), adds the
// particles' kinetic energy, the network's stored contact energy and the walls' own. Its
// fields are its part of a checkpoint (DemState derives from it). Towards MPI: `dissipated`
// is per owned grain, and a rank's totals are summed over ranks in rank order. SI units (J).
#pragma once
#include <cstddef>
#include <vector>

#include "dem/contact_network.hpp"
#include "dem/particles.hpp"
#include "dem/wall.hpp"

namespace kolsky::dem {

/// Energy ledger (J). kinetic + elastic + dissipated - wall_work is conserved up to the
/// integration error (and the non-potential part of Mindlin's overlap-dependent k_t).
struct DemEnergy {
  double kinetic = 0;     ///< particles (translation + rotation) and the tube's radial mode
  double elastic = 0;     ///< contact springs and the tube's hoop spring
  double dissipated = 0;  ///< dashpots, sliding, rolling friction and rolling retardation
  double wall_work = 0;   ///< work done by moving planes on the particles
  /// Energy taken out by particle edits: the removed grains' kinetic energy and the energy
  /// stored in their contacts, minus the added grains' kinetic and contact energy (J). So
  /// kinetic + elastic + dissipated + edited - wall_work stays conserved across edits.
  double edited = 0;
};

struct EnergyLedger {
  std::vector<double> dissipated;  ///< per grain, J
  double removed_dissipated = 0;   ///< dissipation of grains edits removed, J
  double edited_energy = 0;        ///< DemEnergy::edited, J
};

/// The ledger's reading: the particles' kinetic energy, the contacts' stored energy (pairs,
/// then wall contacts), then each wall's kinetic, elastic energy and work in slot order, the
/// grains' dissipation in index order plus what removed grains had, and the edits' share.
DemEnergy energy(const EnergyLedger& ledger, const Particles& p, const ContactNetwork& net,
                 const std::vector<Wall>& walls);
/// Throws kolsky::InputError ("dem.state") unless there is one dissipation per grain.
void check_ledger_state(const EnergyLedger& ledger, std::size_t n_particles);
/// An edit: grains i with old_to_new[i] < 0 give their dissipation to removed_dissipated (in
/// index order); the survivors keep theirs (new k <- old survivors[k]), and the grains added
/// up to n_new start with none.
void carry_ledger(EnergyLedger& ledger, const std::vector<int>& old_to_new, const std::vector<int>& survivors,
                  std::size_t n_new);
/// A re-sort: new grain k has the dissipation of old grain order[k].
void permute_ledger(EnergyLedger& ledger, const std::vector<int>& order);
/// Books what an edit took out: the kinetic and stored energy before it minus after it.
void book_edit(EnergyLedger& ledger, const DemEnergy& before, const DemEnergy& after);

}  // namespace kolsky::dem
