// Grain-pair forces of the Hertz-Mindlin law through the batch kernel (hertz_mindlin_batch.hpp):
// the same contacts, values and summation order as pair_forces (contact_forces.cpp),
// restructured so that the law itself runs branch-free over the touching contacts.
// Per block of up to kCapacity listed pairs: (1) test which pairs touch, recording the touching
// ones without a branch, and clear the histories of the separated ones; (2) copy the inputs of
// the touching ones into the batch (several materials; with one, the law reads them where they
// lie); (3) evaluate the law into the batch's outputs; (4) store the partner's side and the
// history, and sum the owner's side in pair order (a run of an owner may span blocks).
// The owners are swept in fixed blocks of DemOptions::owner_block grains, as pair_forces does:
// a partner in the owner's block receives its side directly, the others through their slot.
#include <omp.h>

#include <cstdint>
#include <memory>

#include "dem/contact_forces.hpp"
#include "dem/hertz_mindlin_batch.hpp"

namespace kolsky::dem {

namespace {

constexpr int kCap = HertzMindlinBatch::kCapacity;
constexpr int kAhead = 16;  // pairs: about the latency of an L3 hit over a pair's work

// (1) Which of the listed pairs [k0, k1) touch (d2 >= (r_i + r_j)^2: apart, as in
// pair_forces); their indices go to `touching`, without a branch. Returns how many.
[[gnu::always_inline]] inline int find_touching(const PairArrays& a, int k0, int k1, int k_end, int* touching) {
  int m = 0;
  for (int k = k0; k < k1; ++k) {
    const int i = a.pi[k], j = a.pj[k];
    // Partners a grid layer away (thousands of grains) miss the L2 cache: request their
    // position some pairs ahead. The histories are read in (2) and written in (4) for
    // touching pairs only, so the hardware sees no steady stream: request them here too, in
    // pair order. (Requesting the partner's velocity, spin and force line as well no longer
    // pays: docs/dem.md, "Performance", item 11.)
    if (k + kAhead < k_end) {
      __builtin_prefetch(&a.x[a.pj[k + kAhead]]);
      __builtin_prefetch(&a.hist[k + kAhead], 1);
    }
    const Vec3 d = a.x[j] - a.x[i];
    const double rsum = a.rad[i] + a.rad[j];
    const bool touch = !(norm2(d) >= rsum * rsum);
    // Separated since the last step: its slot must read zero, and it forgets its tangential
    // spring. Only a pair active at the last evaluation can hold a non-zero history (rebuild()
    // marks carried histories active), so the history is read on this rare branch only, not
    // for every listed pair (read first: most are zero).
    const bool separated = a.active[k] > static_cast<unsigned char>(touch);
    if (separated) {
      a.separated(k);
      const Vec3& h = a.hist[k];
      if (h.x != 0 || h.y != 0 || h.z != 0) a.hist[k] = Vec3{};
    }
    a.active[k] = touch;
    touching[m] = k;
    m += touch;
  }
  return m;
}

// (2) The inputs of the m touching pairs, packed into the batch, with each pair's material
// constants (more than one material; with one, the law reads the inputs where they lie).
[[gnu::always_inline]] inline void pack_batch(const PairArrays& a, const HertzMindlinConstants* table, int n_mat,
                                              const int* touching, int m, HertzMindlinBatch& b) {
  for (int t = 0; t < m; ++t) {
    const int k = touching[t], i = a.pi[k], j = a.pj[k];
    const Vec3 d = a.x[j] - a.x[i], dv = a.v[j] - a.v[i];
    b.dx[t] = d.x, b.dy[t] = d.y, b.dz[t] = d.z;
    b.ri[t] = a.rad[i], b.rj[t] = a.rad[j], b.r_eff[t] = a.r_eff[k], b.m_eff[t] = a.m_eff[k];
    b.dvx[t] = dv.x, b.dvy[t] = dv.y, b.dvz[t] = dv.z;
    b.wix[t] = a.w[i].x, b.wiy[t] = a.w[i].y, b.wiz[t] = a.w[i].z;
    b.wjx[t] = a.w[j].x, b.wjy[t] = a.w[j].y, b.wjz[t] = a.w[j].z;
    b.hx[t] = a.hist[k].x, b.hy[t] = a.hist[k].y, b.hz[t] = a.hist[k].z;
    const HertzMindlinConstants& c = table[a.mat[i] * n_mat + a.mat[j]];
    b.k_force[t] = c.force, b.k_stiffness[t] = c.stiffness, b.k_damping[t] = c.damping;
    b.k_shear[t] = c.shear, b.k_friction[t] = c.friction;
    b.k_tdamp[t] = c.tangential_damping_scale;
  }
}

// The owner whose sums are open, and the sums (as pair_forces' registers): an owner's side is
// summed in pair order, and its run may span batches.
struct OwnerSums {
  int cur = 0;
  Vec3 F{}, T{};
  double D = 0;
  // Closes `cur` and opens `owner` (> cur).
  [[gnu::always_inline]] void close_until(const PairArrays& a, int owner) {
    a.f[cur] += F;  // after the sides it received as a partner within its block
    a.tq[cur] += T;
    a.diss[cur] += D;
    for (int q = cur + 1; q < owner; ++q) a.diss[q] += 0.0;  // owners without touching pairs
    cur = owner;
    F = T = Vec3{};
    D = 0;
  }
};

// (4) Partner's side to it (same block) or its slot; owner's side summed in pair order.
[[gnu::always_inline]] inline void scatter_batch(const PairArrays& a, const int* touching, int m,
                                                 const HertzMindlinBatch& b, OwnerSums& s) {
  for (int t = 0; t < m; ++t) {
    const int k = touching[t], i = a.pi[k];
    if (i != s.cur) s.close_until(a, i);
    const Vec3 force{b.fx[t], b.fy[t], b.fz[t]};
    s.F += force;
    s.T += Vec3{b.tix[t], b.tiy[t], b.tiz[t]};
    s.D += 0.5 * b.dissipated[t];
    a.partner_side(k, a.pj[k], force, {b.tjx[t], b.tjy[t], b.tjz[t]}, 0.5 * b.dissipated[t], b.elastic[t]);
    a.hist[k] = {b.hx[t], b.hy[t], b.hz[t]};
  }
}

}  // namespace

void hertz_mindlin_pair_forces(const PairArrays& arrays, const HertzMindlinConstants* table, int n_mat,
                               double dt) {
  // A local copy of the views, as a local: the flag stores (unsigned char) cannot alias it.
  const PairArrays a = arrays;
  // Called by every thread of evaluate_contacts' parallel region (no barrier at the end); the
  // block below is this thread's share. Each thread takes a contiguous run of whole owner
  // blocks; the results do not depend on the split (each contact is evaluated alone, each
  // grain's sums are formed within its block in pair order, and its cross-block slots are
  // added by gather() in slot order).
  const int nt = omp_get_num_threads(), th = omp_get_thread_num();
  const int b0 = static_cast<int>(static_cast<std::int64_t>(a.n_blocks) * th / nt);
  const int b1 = static_cast<int>(static_cast<std::int64_t>(a.n_blocks) * (th + 1) / nt);
  auto batch = std::make_unique<HertzMindlinBatch>();
  HertzMindlinBatch& b = *batch;
  int touching[kCap];
  // One material (every scene of the reproductions and the benchmark): the law reads the
  // touching pairs' inputs where they lie, and the constants of the one material pair, without
  // the copy into the batch's input lanes (docs/dem.md, "Performance": +6-7 % on the step).
  const bool one_material = n_mat == 1;
  const GatheredContacts gathered{touching, a.pi, a.pj, a.x, a.v, a.w, a.rad, a.r_eff, a.m_eff, a.hist, table[0]};
  OwnerSums sums;
  for (int blk = b0; blk < b1; ++blk) {
    const int i0 = a.block_first[blk], i1 = a.block_first[blk + 1];
    for (int q = i0; q < i1; ++q) a.f[q] = a.tq[q] = Vec3{};  // partner sides accumulate here
    sums.cur = i0;
    for (int k0 = a.first[i0], k_end = a.first[i1]; k0 < k_end; k0 += kCap) {
      const int k1 = k0 + kCap < k_end ? k0 + kCap : k_end;
      const int m = find_touching(a, k0, k1, k_end, touching);
      if (one_material) {  // (2) and (3) in one
        evaluate_gathered(gathered, b, m, dt);
      } else {
        pack_batch(a, table, n_mat, touching, m, b);
        evaluate(b, m, dt);  // (3) the law
      }
      scatter_batch(a, touching, m, b, sums);
    }
    sums.close_until(a, i1);
  }
}

}  // namespace kolsky::dem
