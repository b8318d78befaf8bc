// Contact kernels of DemSystem: grain-grain pairs and walls (wall.hpp), each a tight loop
// over a contiguous contact list with the law resolved once outside it (std::visit), writing
// one slot per contact; then the per-particle gather in a fixed order (dem_system.hpp).
// Geometry: n from i to j, overlap delta = r_i + r_j - |x_j - x_i|, contact point at
// a_i = r_i - delta/2 from i (a_j = r_j - delta/2 from j, so both points coincide); for a wall
// the contact point lies on the wall surface, a = r - delta.
#include <algorithm>
#include <cmath>
#include <limits>

#include "dem/dem_system.hpp"
#include "dem/hertz_mindlin_batch.hpp"

namespace kolsky::dem {

DemSystem::PairArrays DemSystem::pair_arrays() {
  const int n = static_cast<int>(p_.size());
  ContactNetwork& c = net_;
  return {c.pairs.first.data(), c.pairs.i.data(), c.pairs.j.data(), c.pair_slot.data(),
          p_.material.data(), p_.x.data(), p_.v.data(), p_.omega.data(), p_.radius.data(),
          p_.mass.data(), c.pairs.history.data(), p_.f.data(), p_.torque.data(),
          ledger_.dissipated.data(), c.pair_out.elastic.data(), c.pair_out.out.data(),
          c.pair_out.active.data(), c.block_first.data(), n,
          static_cast<int>(c.block_first.size()) - 1};
}

template <class Law>
void DemSystem::pair_forces(const Law& law, double dt) {
  // One pass per owner particle i over its pairs k (j > i), in fixed blocks of opt_.owner_block
  // owners: i's side is summed in registers and added once; j's side is added to j at once if
  // j lies in i's block (as the partner's owners all do, in pair order, before j's own sum),
  // else stored in j's slot for gather(). So each grain's sums have one order for any number
  // of threads, and the batched kernel (dem_forces_batched.cpp) keeps the same order.
  // Work-shared within compute_forces' region; no barrier at the end (the walls follow).
  const PairArrays a = pair_arrays();
  const int n_blocks = a.n_blocks;
#pragma omp for schedule(static) nowait
  for (int blk = 0; blk < n_blocks; ++blk) {
    const int i0 = a.block_first[blk], i1 = a.block_first[blk + 1];
    for (int q = i0; q < i1; ++q) a.f[q] = a.tq[q] = Vec3{};
    for (int i = i0; i < i1; ++i) {
      const Vec3 xi = a.x[i], vi = a.v[i], wi = a.w[i];
      const double ri = a.rad[i], mi = a.mass[i];
      const int mat_i = a.mat[i];
      Vec3 F{}, T{};
      double D = 0;
      for (int k = a.first[i]; k < a.first[i + 1]; ++k) {
        const int j = a.pj[k];
        const Vec3 d = a.x[j] - xi;
        const double rsum = ri + a.rad[j];
        const double d2 = norm2(d);
        if (d2 >= rsum * rsum) {
          if (a.active[k]) a.separated(k);
          a.active[k] = 0;
          // A separated contact forgets its tangential spring (read first: most are zero).
          if (a.hist[k].x != 0 || a.hist[k].y != 0 || a.hist[k].z != 0) a.hist[k] = Vec3{};
          continue;
        }
        const double dist = std::sqrt(d2);
        ContactGeometry g;
        g.normal = dist > 0 ? (1.0 / dist) * d : Vec3{0, 0, 1};
        g.overlap = rsum - dist;
        const double ai = ri - 0.5 * g.overlap, aj = a.rad[j] - 0.5 * g.overlap;
        g.v_contact = a.v[j] - vi - cross(ai * wi + aj * a.w[j], g.normal);
        g.omega_rel = wi - a.w[j];
        g.r_i = ri;
        g.r_j = a.rad[j];
        g.r_eff = ri * a.rad[j] / rsum;
        g.m_eff = mi * a.mass[j] / (mi + a.mass[j]);
        const ContactResult r = law.pair(mat_i, a.mat[j]).force(g, a.hist[k], dt);
        const Vec3 nf = cross(g.normal, r.force);
        F += r.force;
        T += ai * nf + r.rolling_torque;
        D += 0.5 * r.dissipated;
        a.partner_side(k, j, r.force, aj * nf - r.rolling_torque, 0.5 * r.dissipated,
                       r.elastic_energy);
        a.active[k] = 1;
      }
      a.f[i] += F;  // after the sides it received as a partner within its block
      a.tq[i] += T;
      a.diss[i] += D;
    }
  }
}

namespace {
// Grain-wall contact of a grain (radius r, mass m, velocity v, spin w) given the unit normal n
// toward the wall and the wall's velocity. Returns the result; `torque` gets the moment on the
// grain about its centre (contact point on the wall surface, lever a = r - delta).
template <class WallPair>
ContactResult wall_contact(const WallPair& pair, double overlap, const Vec3& n,
                           const Vec3& v_wall, double r_eff, double r, double m, const Vec3& v,
                           const Vec3& w, Vec3& history, double dt, Vec3& torque) {
  ContactGeometry g;
  g.normal = n;
  g.overlap = overlap;
  const double a = r - overlap;
  g.v_contact = v_wall - v - a * cross(w, n);
  g.omega_rel = w;
  g.r_i = r;
  g.r_j = std::numeric_limits<double>::infinity();
  g.r_eff = r_eff;
  g.m_eff = m;
  const ContactResult res = pair.force(g, history, dt);
  torque = a * cross(n, res.force) + res.rolling_torque;
  return res;
}
}  // namespace

// The contacts of one wall with its law and shape resolved (compute_forces visits both once):
// the gap, normal, velocity and R* of the wall at each candidate grain (wall.hpp). The
// overlap -gap is bitwise the one the kernel has always used (wall.hpp says why).
template <class Law, class Shape>
void DemSystem::wall_forces(const Law& law, const Shape& shape, int slot, double dt) {
  const auto c0 = static_cast<std::ptrdiff_t>(net_.wall_first[slot]);
  const auto c1 = static_cast<std::ptrdiff_t>(net_.wall_first[slot + 1]);
  ContactStore& out = net_.wall_out;
#pragma omp for schedule(dynamic, kWallChunk) nowait
  for (std::ptrdiff_t c = c0; c < c1; ++c) {
    const int i = net_.wall_particle[c];
    const Vec3& x = p_.x[i];
    const double r = p_.radius[i];
    const double overlap = -gap_at(shape, x, r);
    if (overlap <= 0) {
      out.active[c] = 0;
      net_.wall_history[c] = Vec3{};
      continue;
    }
    Vec3 torque;
    const ContactResult res =
        wall_contact(law.pair(p_.material[i]), overlap, normal_at(shape, x), velocity_at(shape, x),
                     contact_radius_at(shape, x, r), r, p_.mass[i], p_.v[i], p_.omega[i], net_.wall_history[c], dt, torque);
    out.out[c] = {res.force, torque, res.dissipated, res.elastic_energy};
    net_.wall_normal[c] = res.normal_force;
    net_.wall_elastic_normal[c] = res.elastic_normal_force;
    out.active[c] = 1;
  }
}

void DemSystem::gather() {
  // Adds to each particle what pair_forces stored for it as a partner of an owner in another
  // block (contiguous slots, pair order), then its wall contacts, in list order.
  const auto n = static_cast<std::ptrdiff_t>(p_.size());
  const int* pfirst = net_.partner_first.data();
  const int* wfirst = net_.wall_first_of.data();
  const int* wentry = net_.wall_entry.data();
  const ContactStore& po = net_.pair_out;
  const ContactStore& wo = net_.wall_out;
  Vec3* f = p_.f.data();
  Vec3* tq = p_.torque.data();
  double* diss = ledger_.dissipated.data();
#pragma omp for schedule(static)
  for (std::ptrdiff_t q = 0; q < n; ++q) {
    Vec3 F = f[q], T = tq[q];
    double D = 0;
    for (int s = pfirst[q]; s < pfirst[q + 1]; ++s) {  // zero where not touching
      const ContactOut& o = po.out[s];
      F += o.force;
      T += o.torque;
      D += o.dissipated;
    }
    for (int s = wfirst[q]; s < wfirst[q + 1]; ++s) {
      const int c = wentry[s];
      if (!wo.active[c]) continue;
      const ContactOut& o = wo.out[c];
      F += o.force;
      T += o.torque;
      D += o.dissipated;
    }
    f[q] = F;
    tq[q] = T;
    diss[q] += D;
  }
}

void DemSystem::compute_forces(double dt) {
  if (particles_changed_) refresh_after_edit();
  if (needs_rebuild(net_, skin_, walls_)) rebuild();
  const auto* hm = std::get_if<HertzMindlin>(&law_);
  const bool batched = hm && opt_.batched_hertz_mindlin;
  const std::vector<HertzMindlinConstants> table =
      batched ? hertz_mindlin_table(*hm) : std::vector<HertzMindlinConstants>{};
  const int n_mat = batched ? hm->n_materials() : 0;
  // One region for the whole evaluation. The pair sweep splits whole owner blocks statically
  // (17 blocks of pack_35k split 8 / 9); a thread that finishes its blocks goes on to the wall
  // contacts, handed out in chunks as threads come free, so the walls fill the gap instead of
  // waiting for it. Wall contacts read only positions, velocities and spins and write their
  // own slots, so they may run beside the sweep, and which thread takes which chunk changes
  // no result. The barrier then separates the slots' writers from gather().
#pragma omp parallel if (static_cast<std::ptrdiff_t>(p_.size()) >= kParallelMin)
  {
    if (batched)
      hertz_mindlin_pair_forces(table.data(), n_mat, dt);
    else
      std::visit([&](const auto& law) { pair_forces(law, dt); }, law_);
    // By slot: planes, then cylinders, the order of every wall sum.
    for (int w = 0; w < static_cast<int>(walls_.size()); ++w)
      std::visit([&](const auto& shape) {
        std::visit([&](const auto& law) { wall_forces(law, shape, w, dt); }, shape.wall.law);
      }, walls_[w].shape);
#pragma omp barrier
    gather();
  }
  // Wall resultants in candidate order (deterministic), and the planes' work on the grains
  // by the trapezoid rule over the plane's displacement since the last evaluation.
  for (int w = 0; w < static_cast<int>(walls_.size()); ++w) {
    double sum = 0;
    for (int c = net_.wall_first[w]; c < net_.wall_first[w + 1]; ++c)
      if (net_.wall_out.active[c]) sum += net_.wall_normal[c];
    record_force(walls_[w], sum);
  }
  forces_valid_ = true;
}

}  // namespace kolsky::dem
