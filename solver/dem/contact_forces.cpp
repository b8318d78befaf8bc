// Contact kernels (contact_forces.hpp): grain-grain pairs and walls (wall.hpp), each a tight
// loop over a contiguous contact list with the law resolved once outside it (std::visit),
// writing one slot per contact; then the per-particle gather in a fixed order.
// Geometry: n from i to j, overlap delta = r_i + r_j - |x_j - x_i|, contact point at
// a_i = r_i - delta/2 from i (a_j = r_j - delta/2 from j, so both points coincide); for a wall
// the contact point lies on the wall surface, a = r - delta.
#include "dem/contact_forces.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "dem/contact_hertz_mindlin.hpp"
#include "dem/hertz_mindlin_batch.hpp"

namespace kolsky::dem {

PairArrays::PairArrays(ContactNetwork& c, Particles& p, std::vector<double>& dissipated)
    : first(c.pairs.first.data()), pi(c.pairs.i.data()), pj(c.pairs.j.data()), slot(c.pair_slot.data()),
      mat(p.material.data()), x(p.x.data()), v(p.v.data()), w(p.omega.data()), rad(p.radius.data()),
      mass(p.mass.data()), r_eff(c.pair_r_eff.data()), m_eff(c.pair_m_eff.data()), hist(c.pairs.history.data()), f(p.f.data()), tq(p.torque.data()),
      diss(dissipated.data()), stored(c.pair_out.elastic.data()), out(c.pair_out.out.data()),
      active(c.pair_out.active.data()), block_first(c.block_first.data()), n(static_cast<int>(p.size())),
      n_blocks(static_cast<int>(c.block_first.size()) - 1) {}

namespace {

// Loops shorter than this run on one thread: a parallel region costs microseconds, which
// would dominate the one- and two-particle verification runs.
constexpr std::ptrdiff_t kParallelMin = 2048;
// Wall contacts per chunk handed to a free thread (evaluate_contacts): small enough to even
// out the threads' sweeps, large enough that taking a chunk (one atomic) costs nothing.
constexpr int kWallChunk = 256;

template <class Law>
void pair_forces(const PairArrays& arrays, const Law& law, double dt) {
  // One pass per owner particle i over its pairs k (j > i), in fixed blocks of owner_block
  // owners: i's side is summed in registers and added once; j's side is added to j at once if
  // j lies in i's block (as the partner's owners all do, in pair order, before j's own sum),
  // else stored in j's slot for gather(). So each grain's sums have one order for any number
  // of threads, and the batched kernel (contact_forces_batched.cpp) keeps the same order.
  // Work-shared within evaluate_contacts' region; no barrier at the end (the walls follow).
  // A local copy of the views, as a local: the flag stores (unsigned char) cannot alias it.
  const PairArrays a = arrays;
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
        g.r_eff = pair_effective(ri, a.rad[j]);
        g.m_eff = pair_effective(mi, a.mass[j]);
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

// The contacts of one wall with its law and shape resolved (evaluate_contacts visits both once):
// the gap, normal, velocity and R* of the wall at each candidate grain (wall.hpp). The
// overlap -gap is bitwise the one the kernel has always used (wall.hpp says why).
template <class Law, class Shape>
void wall_forces(ContactNetwork& net, const Particles& p, const Law& law, const Shape& shape, int slot, double dt) {
  const auto c0 = static_cast<std::ptrdiff_t>(net.wall_first[slot]);
  const auto c1 = static_cast<std::ptrdiff_t>(net.wall_first[slot + 1]);
  ContactStore& out = net.wall_out;
#pragma omp for schedule(dynamic, kWallChunk) nowait
  for (std::ptrdiff_t c = c0; c < c1; ++c) {
    const int i = net.wall_particle[c];
    const Vec3& x = p.x[i];
    const double r = p.radius[i];
    const double overlap = -gap_at(shape, x, r);
    if (overlap <= 0) {
      out.active[c] = 0;
      net.wall_history[c] = Vec3{};
      continue;
    }
    Vec3 torque;
    const ContactResult res =
        wall_contact(law.pair(p.material[i]), overlap, normal_at(shape, x), velocity_at(shape, x),
                     contact_radius_at(shape, x, r), r, p.mass[i], p.v[i], p.omega[i], net.wall_history[c], dt, torque);
    out.out[c] = {res.force, torque, res.dissipated, res.elastic_energy};
    net.wall_normal[c] = res.normal_force;
    net.wall_elastic_normal[c] = res.elastic_normal_force;
    out.active[c] = 1;
  }
}

void gather(const ContactNetwork& net, Particles& p, std::vector<double>& dissipated) {
  // Adds to each particle what pair_forces stored for it as a partner of an owner in another
  // block (contiguous slots, pair order), then its wall contacts, in list order.
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  const int* pfirst = net.partner_first.data();
  const int* wfirst = net.wall_first_of.data();
  const int* wentry = net.wall_entry.data();
  const ContactStore& po = net.pair_out;
  const ContactStore& wo = net.wall_out;
  Vec3* f = p.f.data();
  Vec3* tq = p.torque.data();
  double* diss = dissipated.data();
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

// r* and m* of every listed pair (ContactNetwork::pair_r_eff), as pair_forces forms them per
// contact.
void form_pair_constants(ContactNetwork& net, const Particles& p) {
  const std::size_t n_pairs = net.pairs.size();
  net.pair_r_eff.resize(n_pairs);
  net.pair_m_eff.resize(n_pairs);
  for (std::size_t k = 0; k < n_pairs; ++k) {
    const int i = net.pairs.i[k], j = net.pairs.j[k];
    net.pair_r_eff[k] = pair_effective(p.radius[i], p.radius[j]);
    net.pair_m_eff[k] = pair_effective(p.mass[i], p.mass[j]);
  }
}

}  // namespace

void evaluate_contacts(ContactNetwork& net, Particles& p, std::vector<double>& dissipated,
                       const ContactLaw& grain_law, bool batched_hm, std::vector<Wall>& walls, double dt) {
  const auto* hm = std::get_if<HertzMindlin>(&grain_law);
  const bool batched = hm && batched_hm;
  const std::vector<HertzMindlinConstants> table =
      batched ? hertz_mindlin_table(*hm) : std::vector<HertzMindlinConstants>{};
  const int n_mat = batched ? hm->n_materials() : 0;
  // One region for the whole evaluation. The pair sweep splits whole owner blocks statically
  // (17 blocks of pack_35k split 8 / 9); a thread that finishes its blocks goes on to the wall
  // contacts, handed out in chunks as threads come free, so the walls fill the gap instead of
  // waiting for it. Wall contacts read only positions, velocities and spins and write their
  // own slots, so they may run beside the sweep, and which thread takes which chunk changes
  // no result. The barrier then separates the slots' writers from gather().
  if (batched && net.pair_r_eff.size() != net.pairs.size()) form_pair_constants(net, p);
  const PairArrays arrays(net, p, dissipated);
#pragma omp parallel if (static_cast<std::ptrdiff_t>(p.size()) >= kParallelMin)
  {
    if (batched)
      hertz_mindlin_pair_forces(arrays, table.data(), n_mat, dt);
    else
      std::visit([&](const auto& law) { pair_forces(arrays, law, dt); }, grain_law);
    // By slot: planes, then cylinders, the order of every wall sum.
    for (int w = 0; w < static_cast<int>(walls.size()); ++w)
      std::visit([&](const auto& shape) {
        std::visit([&](const auto& law) { wall_forces(net, p, law, shape, w, dt); }, shape.wall.law);
      }, walls[w].shape);
#pragma omp barrier
    gather(net, p, dissipated);
  }
  // Wall resultants in candidate order (deterministic), and the planes' work on the grains
  // by the trapezoid rule over the plane's displacement since the last evaluation.
  for (int w = 0; w < static_cast<int>(walls.size()); ++w) {
    double sum = 0;
    for (int c = net.wall_first[w]; c < net.wall_first[w + 1]; ++c)
      if (net.wall_out.active[c]) sum += net.wall_normal[c];
    record_force(walls[w], sum);
  }
}

}  // namespace kolsky::dem
