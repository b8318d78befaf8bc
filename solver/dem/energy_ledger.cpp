// The DEM energy ledger (energy_ledger.hpp): its reading and its carry through edits.
#include "dem/energy_ledger.hpp"

#include "core/errors.hpp"

namespace kolsky::dem {

DemEnergy energy(const EnergyLedger& ledger, const Particles& p, const ContactNetwork& net,
                 const std::vector<Wall>& walls) {
  DemEnergy e;
  e.kinetic = p.kinetic_energy();
  e.elastic = stored_energy(net);  // pairs in pair order, then the wall contacts
  // A ring's energies and a plane's work; the zeros the other shapes add change no sum (a
  // sum of these terms is never -0).
  for (const Wall& w : walls) {
    const WallEnergy we = energy_of(w);
    e.kinetic += we.kinetic;
    e.elastic += we.elastic;
    e.wall_work += we.work;
  }
  for (double d : ledger.dissipated) e.dissipated += d;
  e.dissipated += ledger.removed_dissipated;
  e.edited = ledger.edited_energy;
  return e;
}

void check_ledger_state(const EnergyLedger& ledger, std::size_t n_particles) {
  if (ledger.dissipated.size() != n_particles)
    throw InputError("", "dem.state", "dissipated energy: one value per particle needed");
}

void carry_ledger(EnergyLedger& ledger, const std::vector<int>& old_to_new, const std::vector<int>& survivors,
                  std::size_t n_new) {
  for (std::size_t i = 0; i < old_to_new.size(); ++i)
    if (old_to_new[i] < 0) ledger.removed_dissipated += ledger.dissipated[i];
  permute_ledger(ledger, survivors);
  ledger.dissipated.resize(n_new, 0.0);
}

void permute_ledger(EnergyLedger& ledger, const std::vector<int>& order) {
  std::vector<double> d(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) d[k] = ledger.dissipated[static_cast<std::size_t>(order[k])];
  ledger.dissipated.swap(d);
}

void book_edit(EnergyLedger& ledger, const DemEnergy& before, const DemEnergy& after) {
  ledger.edited_energy += (before.kinetic + before.elastic) - (after.kinetic + after.elastic);
}

}  // namespace kolsky::dem
