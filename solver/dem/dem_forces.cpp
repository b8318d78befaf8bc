// Contact kernels of DemSystem: grain-grain pairs, planes and cylinders, each a tight loop
// over a contiguous contact list with the law resolved once outside it (std::visit), writing
// one slot per contact; then the per-particle gather in a fixed order (dem_system.hpp).
// Geometry: n from i to j, overlap delta = r_i + r_j - |x_j - x_i|, contact point at
// a_i = r_i - delta/2 from i (a_j = r_j - delta/2 from j, so both points coincide); for a wall
// the contact point lies on the wall surface, a = r - delta.
#include <algorithm>
#include <cmath>
#include <limits>

#include "dem/dem_system.hpp"

namespace kolsky::dem {

template <class Law>
void DemSystem::pair_forces(const Law& law, double dt) {
  // One pass per owner particle i over its pairs k (j > i), in fixed blocks of opt_.owner_block
  // owners: i's side is summed in registers and added once; j's side is added to j at once if
  // j lies in i's block (as the partner's owners all do, in pair order, before j's own sum),
  // else stored in j's slot for gather(). So each grain's sums have one order for any number
  // of threads, and the batched kernel (dem_forces_batched.cpp) keeps the same order.
  const int n = static_cast<int>(p_.size());
  const int* first = pairs_.first.data();
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
  double* stored = pair_out_.elastic.data();
  const int block = opt_.owner_block, n_blocks = n / block + (n % block != 0);
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (int blk = 0; blk < n_blocks; ++blk) {
    const int i0 = blk * block, i1 = i0 + std::min(n - i0, block);
    for (int q = i0; q < i1; ++q) f[q] = tq[q] = Vec3{};
    for (int i = i0; i < i1; ++i) {
      const Vec3 xi = x[i], vi = v[i], wi = w[i];
      const double ri = rad[i], mi = mass[i];
      const int mat_i = mat[i];
      Vec3 F{}, T{};
      double D = 0;
      for (int k = first[i]; k < first[i + 1]; ++k) {
        const int j = pj[k], sk = slot[k];
        const Vec3 d = x[j] - xi;
        const double rsum = ri + rad[j];
        const double d2 = norm2(d);
        if (d2 >= rsum * rsum) {
          if (active[k]) {  // separated: its slot and stored energy read zero
            if (sk >= 0) out[sk] = ContactOut{};
            stored[k] = 0;
          }
          active[k] = 0;
          // A separated contact forgets its tangential spring (read first: most are zero).
          if (hist[k].x != 0 || hist[k].y != 0 || hist[k].z != 0) hist[k] = Vec3{};
          continue;
        }
        const double dist = std::sqrt(d2);
        ContactGeometry g;
        g.normal = dist > 0 ? (1.0 / dist) * d : Vec3{0, 0, 1};
        g.overlap = rsum - dist;
        const double ai = ri - 0.5 * g.overlap, aj = rad[j] - 0.5 * g.overlap;
        g.v_contact = v[j] - vi - cross(ai * wi + aj * w[j], g.normal);
        g.omega_rel = wi - w[j];
        g.r_i = ri;
        g.r_j = rad[j];
        g.r_eff = ri * rad[j] / rsum;
        g.m_eff = mi * mass[j] / (mi + mass[j]);
        const ContactResult r = law.pair(mat_i, mat[j]).force(g, hist[k], dt);
        const Vec3 nf = cross(g.normal, r.force);
        F += r.force;
        T += ai * nf + r.rolling_torque;
        D += 0.5 * r.dissipated;
        const Vec3 torque_j = aj * nf - r.rolling_torque;
        if (sk < 0) {  // partner in this block: added now, in pair order
          f[j] += -r.force;
          tq[j] += torque_j;
          diss[j] += 0.5 * r.dissipated;
        } else {
          out[sk] = {-r.force, torque_j, 0.5 * r.dissipated, 0.0};
        }
        stored[k] = r.elastic_energy;
        active[k] = 1;
      }
      f[i] += F;  // after the sides it received as a partner within its block
      tq[i] += T;
      diss[i] += D;
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

template <class Law>
void DemSystem::plane_forces(const Law& law, int k, double dt) {
  const PlaneState& s = planes_[k];
  const Vec3 nw = s.wall.normal;
  const Vec3 base = s.wall.point + s.offset * nw;
  const Vec3 v_wall = s.speed * nw;
  const auto c0 = static_cast<std::ptrdiff_t>(wall_first_[k]);
  const auto c1 = static_cast<std::ptrdiff_t>(wall_first_[k + 1]);
  ContactStore& out = wall_out_;
#pragma omp parallel for schedule(static) if (c1 - c0 >= kParallelMin)
  for (std::ptrdiff_t c = c0; c < c1; ++c) {
    const int i = wall_particle_[c];
    const double overlap = p_.radius[i] - dot(p_.x[i] - base, nw);
    if (overlap <= 0) {
      out.active[c] = 0;
      wall_history_[c] = Vec3{};
      continue;
    }
    Vec3 torque;
    const ContactResult r =
        wall_contact(law.pair(p_.material[i]), overlap, -nw, v_wall, p_.radius[i], p_.radius[i],
                     p_.mass[i], p_.v[i], p_.omega[i], wall_history_[c], dt, torque);
    out.out[c] = {r.force, torque, r.dissipated, r.elastic_energy};
    wall_normal_[c] = r.normal_force;
    out.active[c] = 1;
  }
}

template <class Law>
void DemSystem::tube_forces(const Law& law, int k, double dt) {
  const TubeState& t = tubes_[k];
  const double radius = t.wall.radius + t.u;
  const int slot = static_cast<int>(planes_.size()) + k;
  const auto c0 = static_cast<std::ptrdiff_t>(wall_first_[slot]);
  const auto c1 = static_cast<std::ptrdiff_t>(wall_first_[slot + 1]);
  ContactStore& out = wall_out_;
#pragma omp parallel for schedule(static) if (c1 - c0 >= kParallelMin)
  for (std::ptrdiff_t c = c0; c < c1; ++c) {
    const int i = wall_particle_[c];
    const double dx = p_.x[i].x - t.wall.cx, dy = p_.x[i].y - t.wall.cy;
    const double rho = std::sqrt(dx * dx + dy * dy);
    const double r = p_.radius[i];
    const double overlap = r + rho - radius;
    if (overlap <= 0) {
      out.active[c] = 0;
      wall_history_[c] = Vec3{};
      continue;
    }
    const Vec3 n = rho > 0 ? Vec3{dx / rho, dy / rho, 0} : Vec3{1, 0, 0};
    // Concave contact: R* = r R / (R - r) (Hertz only; a linear spring ignores it).
    const double r_eff = radius > r ? r * radius / (radius - r) : r;
    Vec3 torque;
    const ContactResult res =
        wall_contact(law.pair(p_.material[i]), overlap, n, t.u_dot * n, r_eff, r, p_.mass[i],
                     p_.v[i], p_.omega[i], wall_history_[c], dt, torque);
    out.out[c] = {res.force, torque, res.dissipated, res.elastic_energy};
    wall_normal_[c] = res.normal_force;
    out.active[c] = 1;
  }
}

void DemSystem::gather() {
  // Adds to each particle what pair_forces stored for it as a partner of an owner in another
  // block (contiguous slots, pair order), then its wall contacts, in list order.
  const auto n = static_cast<std::ptrdiff_t>(p_.size());
  const int* pfirst = partner_first_.data();
  const int* wfirst = wall_first_of_.data();
  const int* wentry = wall_entry_.data();
  const ContactStore& po = pair_out_;
  const ContactStore& wo = wall_out_;
  Vec3* f = p_.f.data();
  Vec3* tq = p_.torque.data();
  double* diss = dissipated_.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
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
  if (needs_rebuild()) rebuild();
  if (const auto* hm = std::get_if<HertzMindlin>(&law_); hm && opt_.batched_hertz_mindlin)
    hertz_mindlin_pair_forces(*hm, dt);
  else
    std::visit([&](const auto& law) { pair_forces(law, dt); }, law_);
  for (int k = 0; k < static_cast<int>(planes_.size()); ++k)
    std::visit([&](const auto& law) { plane_forces(law, k, dt); }, planes_[k].wall.law);
  for (int k = 0; k < static_cast<int>(tubes_.size()); ++k)
    std::visit([&](const auto& law) { tube_forces(law, k, dt); }, tubes_[k].wall.law);
  gather();
  // Wall resultants in candidate order (deterministic), and the planes' work on the grains
  // by the trapezoid rule over the plane's displacement since the last evaluation.
  for (std::size_t w = 0; w < planes_.size() + tubes_.size(); ++w) {
    double sum = 0;
    for (int c = wall_first_[w]; c < wall_first_[w + 1]; ++c)
      if (wall_out_.active[c]) sum += wall_normal_[c];
    if (w < planes_.size()) {
      PlaneState& s = planes_[w];
      s.work += 0.5 * (s.force + sum) * (s.offset - s.offset_at_force);
      s.offset_at_force = s.offset;
      s.force = sum;
    } else {
      tubes_[w - planes_.size()].force = sum;
    }
  }
  forces_valid_ = true;
}

}  // namespace kolsky::dem
