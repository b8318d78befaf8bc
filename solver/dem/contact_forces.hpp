// One force evaluation of a DEM assembly as a free function over its components (issue 32):
// the particles, the contact network (contact_network.hpp), the energy ledger's per-grain
// dissipation, the grain law and the walls. Grain pairs are swept by owner blocks
// (contact_forces.cpp, or the batched Hertz-Mindlin kernel of contact_forces_batched.cpp),
// wall contacts beside them, then each grain gathers its slots in a fixed order, so results
// are bitwise the same for any OpenMP thread count (docs/dem.md, "Parallel determinism").
// Towards MPI: the same sweep over owned owners; a ghost partner's side lands in its slot,
// which the gather of the owning rank then adds (contact_network.hpp).
#pragma once
#include <vector>

#include "dem/contact_law.hpp"
#include "dem/contact_network.hpp"
#include "dem/particles.hpp"
#include "dem/wall.hpp"

namespace kolsky::dem {

/// Evaluates every contact of the network (its lists valid for the particles: needs_rebuild
/// false) with the grain law `law` and each wall's law: forces and torques into p.f and
/// p.torque (overwritten), dissipation added to dissipated[i] (J), the per-contact outputs and
/// histories into the network (dt > 0 advances the tangential springs; 0 evaluates without
/// advancing), and each wall's resultant (record_force, in candidate order). `batched`: a
/// Hertz-Mindlin grain law through the batched kernel (DemOptions::batched_hertz_mindlin;
/// bitwise the same results).
void evaluate_contacts(ContactNetwork& net, Particles& p, std::vector<double>& dissipated,
                       const ContactLaw& law, bool batched, std::vector<Wall>& walls, double dt);

// --- What the two pair kernels share (contact_forces.cpp, contact_forces_batched.cpp).

/// Raw views of what the pair kernels read and write, with the two steps they must do alike
/// so that both keep one summation order.
struct PairArrays {
  const int *first, *pi, *pj, *slot, *mat;
  const Vec3 *x, *v, *w;
  const double *rad, *mass;
  const double *r_eff, *m_eff;  // per listed pair (ContactNetwork::pair_r_eff, pair_m_eff)
  Vec3 *hist, *f, *tq;
  double *diss, *stored;
  ContactOut* out;
  unsigned char* active;
  const int* block_first;  // owner block b: grains [block_first[b], block_first[b+1])
  int n, n_blocks;         // grains, blocks

  PairArrays(ContactNetwork& net, Particles& p, std::vector<double>& dissipated);

  /// Partner j's side of touching pair k (force on i, torque on j, half the dissipation):
  /// added to j now when j is in the owner's block (slot -1: the partner's owners all come
  /// in pair order before j's own sum), else stored in j's slot for the gather; and the
  /// pair's stored energy.
  void partner_side(int k, int j, const Vec3& force_i, const Vec3& torque_j,
                    double half_dissipated, double elastic) const {
    const int sk = slot[k];
    if (sk < 0) {
      f[j] += -force_i;
      tq[j] += torque_j;
      diss[j] += half_dissipated;
    } else {
      out[sk] = {-force_i, torque_j, half_dissipated, 0.0};
    }
    stored[k] = elastic;
  }
  /// Pair k stopped touching: its slot and stored energy read zero again.
  void separated(int k) const {
    if (slot[k] >= 0) out[slot[k]] = ContactOut{};
    stored[k] = 0;
  }
};

struct HertzMindlinConstants;  // hertz_mindlin_batch.hpp

/// The batched Hertz-Mindlin grain-pair sweep (contact_forces_batched.cpp), called by every
/// thread of the evaluation's parallel region; `table`: hertz_mindlin_table() of the law.
void hertz_mindlin_pair_forces(const PairArrays& a, const HertzMindlinConstants* table, int n_mat, double dt);

}  // namespace kolsky::dem
