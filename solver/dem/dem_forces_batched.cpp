// Grain-pair forces of the Hertz-Mindlin law through the batch kernel (hertz_mindlin_batch.hpp):
// the same contacts, values and summation order as DemSystem::pair_forces (dem_forces.cpp),
// restructured so that the law itself runs branch-free over packed touching contacts.
// Per block of up to kCapacity listed pairs: (1) test which pairs touch, recording the touching
// ones without a branch, and clear the histories of the separated ones; (2) copy the inputs of
// the touching ones into the batch; (3) evaluate the batch; (4) store the partner's side and
// the history, and sum the owner's side in pair order (a run of an owner may span blocks).
// The owners are swept in fixed blocks of DemOptions::owner_block grains, as pair_forces does:
// a partner in the owner's block receives its side directly, the others through their slot.
#include <omp.h>

#include <cstdint>
#include <memory>

#include "dem/dem_system.hpp"
#include "dem/hertz_mindlin_batch.hpp"

namespace kolsky::dem {

void DemSystem::hertz_mindlin_pair_forces(const HertzMindlin& law, double dt) {
  const int n = static_cast<int>(p_.size());
  const int n_mat = law.n_materials();
  std::vector<HertzMindlinConstants> constants;
  constants.reserve(static_cast<std::size_t>(n_mat) * n_mat);
  for (int a = 0; a < n_mat; ++a)
    for (int b = 0; b < n_mat; ++b) constants.push_back(batch_constants(law.pair(a, b)));

  const int* first = pairs_.first.data();
  const int* pi = pairs_.i.data();
  const int* pj = pairs_.j.data();
  Vec3* hist = pairs_.history.data();
  const Vec3* x = p_.x.data();
  const Vec3* v = p_.v.data();
  const Vec3* w = p_.omega.data();
  const double* rad = p_.radius.data();
  const double* mass = p_.mass.data();
  const int* mat = p_.material.data();
  Vec3* f = p_.f.data();
  Vec3* tq = p_.torque.data();
  double* diss = dissipated_.data();
  const int* slot = pair_slot_.data();
  ContactOut* out = pair_out_.out.data();
  unsigned char* active = pair_out_.active.data();
  const HertzMindlinConstants* table = constants.data();
  constexpr int kCap = HertzMindlinBatch::kCapacity;
  constexpr int kAhead = 16;  // pairs: about the latency of an L3 hit over a pair's work

  double* stored = pair_out_.elastic.data();
  const int block = opt_.owner_block, n_blocks = n / block + (n % block != 0);

  // Each thread takes a contiguous run of whole owner blocks; the results do not depend on the
  // split (each contact is evaluated alone, each grain's sums are formed within its block in
  // pair order, and its cross-block slots are added by gather() in slot order).
#pragma omp parallel if (n >= kParallelMin)
  {
    const int nt = omp_get_num_threads(), th = omp_get_thread_num();
    const int b0 = static_cast<int>(static_cast<std::int64_t>(n_blocks) * th / nt);
    const int b1 = static_cast<int>(static_cast<std::int64_t>(n_blocks) * (th + 1) / nt);
    auto batch = std::make_unique<HertzMindlinBatch>();
    HertzMindlinBatch& b = *batch;
    int touching[kCap];
    // The owner whose sums are open, and the sums (as pair_forces' registers).
    int cur = 0;
    Vec3 F{}, T{};
    double D = 0;
    auto close_until = [&](int owner) {  // closes cur and opens `owner` (> cur)
      f[cur] += F;  // after the sides it received as a partner within its block
      tq[cur] += T;
      diss[cur] += D;
      for (int q = cur + 1; q < owner; ++q) diss[q] += 0.0;  // owners without touching pairs
      cur = owner;
      F = T = Vec3{};
      D = 0;
    };
    for (int blk = b0; blk < b1; ++blk) {
      const int i0 = blk * block, i1 = block < n - i0 ? i0 + block : n;
      for (int q = i0; q < i1; ++q) f[q] = tq[q] = Vec3{};  // partner sides accumulate here
      cur = i0;
      for (int k0 = first[i0], k_end = first[i1]; k0 < k_end; k0 += kCap) {
        const int k1 = k0 + kCap < k_end ? k0 + kCap : k_end;
        // (1) Which pairs touch (d2 >= (r_i + r_j)^2: apart, as in pair_forces).
        int m = 0;
        for (int k = k0; k < k1; ++k) {
          const int i = pi[k], j = pj[k];
          // Partners a grid layer away (thousands of grains) miss the L2 cache: request their
          // position some pairs ahead, and now what (2) and (4) will need if the pair touches.
          // The histories are read in (2) and written in (4) for touching pairs only, so the
          // hardware sees no steady stream: request them here too, in pair order.
          if (k + kAhead < k_end) {
            __builtin_prefetch(&x[pj[k + kAhead]]);
            __builtin_prefetch(&hist[k + kAhead], 1);
          }
          __builtin_prefetch(&v[j]);
          __builtin_prefetch(&w[j]);
          const int sk = slot[k];  // -1: partner in this block, its side goes to f[j]
          __builtin_prefetch(sk >= 0 ? static_cast<const void*>(&out[sk]) : &f[j], 1);
          const Vec3 d = x[j] - x[i];
          const double rsum = rad[i] + rad[j];
          const bool touch = !(norm2(d) >= rsum * rsum);
          // Separated since the last step: its slot must read zero, and it forgets its
          // tangential spring. Only a pair active at the last evaluation can hold a non-zero
          // history (rebuild() marks carried histories active), so the history is read on this
          // rare branch only, not for every listed pair (read first: most are zero).
          const bool separated = active[k] > static_cast<unsigned char>(touch);
          if (separated) {
            if (sk >= 0) out[sk] = ContactOut{};
            stored[k] = 0;
            const Vec3& h = hist[k];
            if (h.x != 0 || h.y != 0 || h.z != 0) hist[k] = Vec3{};
          }
          active[k] = touch;
          touching[m] = k;
          m += touch;
        }
        // (2) Inputs of the touching pairs.
        for (int t = 0; t < m; ++t) {
          const int k = touching[t], i = pi[k], j = pj[k];
          const Vec3 d = x[j] - x[i], dv = v[j] - v[i];
          b.dx[t] = d.x, b.dy[t] = d.y, b.dz[t] = d.z;
          b.ri[t] = rad[i], b.rj[t] = rad[j], b.mi[t] = mass[i], b.mj[t] = mass[j];
          b.dvx[t] = dv.x, b.dvy[t] = dv.y, b.dvz[t] = dv.z;
          b.wix[t] = w[i].x, b.wiy[t] = w[i].y, b.wiz[t] = w[i].z;
          b.wjx[t] = w[j].x, b.wjy[t] = w[j].y, b.wjz[t] = w[j].z;
          b.hx[t] = hist[k].x, b.hy[t] = hist[k].y, b.hz[t] = hist[k].z;
          const HertzMindlinConstants& c = table[mat[i] * n_mat + mat[j]];
          b.k_force[t] = c.force, b.k_stiffness[t] = c.stiffness, b.k_damping[t] = c.damping;
          b.k_shear[t] = c.shear, b.k_friction[t] = c.friction;
          b.k_tdamp[t] = c.tangential_damping_scale;
        }
        // (3) The law.
        evaluate(b, m, dt);
        // (4) Partner's side to it (same block) or its slot; owner's side summed in pair order.
        for (int t = 0; t < m; ++t) {
          const int k = touching[t], i = pi[k];
          if (i != cur) close_until(i);
          const Vec3 force{b.fx[t], b.fy[t], b.fz[t]};
          F += force;
          T += Vec3{b.tix[t], b.tiy[t], b.tiz[t]};
          D += 0.5 * b.dissipated[t];
          const int sk = slot[k];
          const Vec3 torque_j{b.tjx[t], b.tjy[t], b.tjz[t]};
          if (sk < 0) {  // partner in this block: added now, in pair order
            const int j = pj[k];
            f[j] += -force;
            tq[j] += torque_j;
            diss[j] += 0.5 * b.dissipated[t];
          } else {
            out[sk] = {-force, torque_j, 0.5 * b.dissipated[t], 0.0};
          }
          stored[k] = b.elastic[t];
          hist[k] = {b.hx[t], b.hy[t], b.hz[t]};
        }
      }
      close_until(i1);
    }
  }
}

}  // namespace kolsky::dem
