// Branch-free Hertz-Mindlin batch kernel (see hertz_mindlin_batch.hpp). Each line mirrors
// HertzMindlinPair::force() and tangential_force() in contact_pieces.hpp; a branch there is a
// select here, with both sides computed (a side that is not selected may hold NaN or inf in
// its lane: harmless, it is discarded). solver/CMakeLists.txt compiles this file with
// -ffp-contract=off: a fused multiply-add would round differently from the scalar kernel.
#include "dem/hertz_mindlin_batch.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace kolsky::dem {

HertzMindlinConstants batch_constants(const HertzMindlinPair& p) {
  return {(4.0 / 3.0) * p.normal.e_star, 2.0 * p.normal.e_star,
          1.8257418583505538 * p.damping.beta, 8.0 * p.tangential.g_star,
          p.tangential.friction, p.tangential_damping_scale};
}

std::vector<HertzMindlinConstants> hertz_mindlin_table(const HertzMindlin& law) {
  const int n_mat = law.n_materials();
  std::vector<HertzMindlinConstants> constants;
  constants.reserve(static_cast<std::size_t>(n_mat) * n_mat);
  for (int a = 0; a < n_mat; ++a)
    for (int b = 0; b < n_mat; ++b) constants.push_back(batch_constants(law.pair(a, b)));
  return constants;
}

namespace {

// One contact's inputs, as either loop below hands them to the law (hertz_mindlin_batch.hpp).
struct LawInputs {
  double dx, dy, dz, ri, rj, r_eff, m_eff, dvx, dvy, dvz, wix, wiy, wiz, wjx, wjy, wjz, hx, hy, hz;
};

// The law, written once, for contact t: reads `in` and the constants, writes lane t of b's
// outputs and its history. Each loop and each instruction-set variant below inlines it, and
// the compiler vectorises the loop for that variant's registers.
[[gnu::always_inline]] inline void law(const LawInputs& in, const HertzMindlinConstants& c, double dt,
                                       HertzMindlinBatch& b, int t) {
  // Geometry (contact_forces.cpp): n = d/|d|, delta = r_i + r_j - |d|, levers a = r - delta/2.
  const double dx = in.dx, dy = in.dy, dz = in.dz;
  const double ri = in.ri, rj = in.rj;
  const double rsum = ri + rj;
  const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double inv = 1.0 / dist;
  const bool apart = dist > 0;
  const double nx = apart ? inv * dx : 0.0, ny = apart ? inv * dy : 0.0,
               nz = apart ? inv * dz : 1.0;
  const double overlap = rsum - dist;
  const double ai = ri - 0.5 * overlap, aj = rj - 0.5 * overlap;
  const double sx = ai * in.wix + aj * in.wjx, sy = ai * in.wiy + aj * in.wjy,
               sz = ai * in.wiz + aj * in.wjz;
  const double vx = in.dvx - (sy * nz - sz * ny), vy = in.dvy - (sz * nx - sx * nz),
               vz = in.dvz - (sx * ny - sy * nx);
  const double r_eff = in.r_eff;  // pair_effective(ri, rj), formed per listed pair
  const double m_eff = in.m_eff;  // pair_effective(mi, mj)

  // Hertz normal piece, Tsuji dashpot, normal_force().
  const double a = std::sqrt(r_eff * overlap);
  const double f_el = c.force * a * overlap;
  const double s_n = c.stiffness * a;
  const double c_n = c.damping * std::sqrt(s_n * m_eff);
  const double vn = vx * nx + vy * ny + vz * nz;
  const double stored_n = 0.0 + 0.4 * f_el * overlap;
  const double lost_n = 0.0 + c_n * vn * vn * dt;
  const double fn = f_el - c_n * vn;
  const double k_t = c.shear * a;
  const double c_t = c_n * c.tangential_damping_scale;

  // tangential_force(): rotate the history onto the tangent plane, keeping its magnitude.
  const double hx = in.hx, hy = in.hy, hz = in.hz;
  const double xn = hx * nx + hy * ny + hz * nz;
  const double before = hx * hx + hy * hy + hz * hz;
  const double px = hx - xn * nx, py = hy - xn * ny, pz = hz - xn * nz;
  const double after = px * px + py * py + pz * pz;
  const double keep = std::sqrt(before / after);
  const bool rotate = xn != 0, rescale = after > 0;
  const double qx = rotate ? (rescale ? px * keep : px) : hx;
  const double qy = rotate ? (rescale ? py * keep : py) : hy;
  const double qz = rotate ? (rescale ? pz * keep : pz) : hz;
  const double vtn = vx * nx + vy * ny + vz * nz;
  const double tx = vx - vtn * nx, ty = vy - vtn * ny, tz = vz - vtn * nz;
  const double ux = qx + dt * tx, uy = qy + dt * ty, uz = qz + dt * tz;
  const double limit = c.friction * f_el;
  const double limit2 = limit * limit;
  const double sfx = k_t * ux, sfy = k_t * uy, sfz = k_t * uz;
  const double spring2 = sfx * sfx + sfy * sfy + sfz * sfz;

  // Sliding: scale back to the Coulomb limit; L x slip dissipated.
  const bool slide = spring2 > limit2;
  const double spring = std::sqrt(spring2);
  const double scale = limit / spring;
  const double lost_slide = limit * (spring - limit) / k_t;
  // Sticking: the dashpot, cut to the largest s in [0, 1] with |ft + s damp| = L.
  const double gx = c_t * tx, gy = c_t * ty, gz = c_t * tz;
  const double ox = sfx + gx, oy = sfy + gy, oz = sfz + gz;
  const bool cap = ox * ox + oy * oy + oz * oz > limit2;
  const double b2 = gx * gx + gy * gy + gz * gz, ab = sfx * gx + sfy * gy + sfz * gz;
  const double disc = ab * ab - b2 * (spring2 - limit2);
  const double s_cap = (-ab + std::sqrt(0.0 < disc ? disc : 0.0)) / b2;
  const double s = cap ? s_cap : 1.0;
  const double lost_stick = s * c_t * (tx * tx + ty * ty + tz * tz) * dt;
  const bool damped = c_t > 0;

  const double ftx = slide ? sfx * scale : (damped ? sfx + s * gx : sfx);
  const double fty = slide ? sfy * scale : (damped ? sfy + s * gy : sfy);
  const double ftz = slide ? sfz * scale : (damped ? sfz + s * gz : sfz);
  const double hnx = slide ? ux * scale : ux, hny = slide ? uy * scale : uy,
               hnz = slide ? uz * scale : uz;
  const double lost = slide ? lost_n + lost_slide : (damped ? lost_n + lost_stick : lost_n);
  b.hx[t] = hnx;
  b.hy[t] = hny;
  b.hz[t] = hnz;
  b.elastic[t] = stored_n + 0.5 * k_t * (hnx * hnx + hny * hny + hnz * hnz);
  b.dissipated[t] = lost;

  // Force on i and the torques about both centres (no rolling moment: +0, -0 as there).
  const double fx = ftx - fn * nx, fy = fty - fn * ny, fz = ftz - fn * nz;
  const double cx = ny * fz - nz * fy, cy = nz * fx - nx * fz, cz = nx * fy - ny * fx;
  b.fx[t] = fx;
  b.fy[t] = fy;
  b.fz[t] = fz;
  b.tix[t] = ai * cx + 0.0;
  b.tiy[t] = ai * cy + 0.0;
  b.tiz[t] = ai * cz + 0.0;
  b.tjx[t] = aj * cx - 0.0;
  b.tjy[t] = aj * cy - 0.0;
  b.tjz[t] = aj * cz - 0.0;
}

// The packed batch: every input and constant from b's lanes.
[[gnu::always_inline]] inline void evaluate_batch(HertzMindlinBatch& b, int count, double dt) {
  for (int t = 0; t < count; ++t) {
    const LawInputs in{b.dx[t],  b.dy[t],  b.dz[t],  b.ri[t],  b.rj[t],  b.r_eff[t], b.m_eff[t],
                       b.dvx[t], b.dvy[t], b.dvz[t], b.wix[t], b.wiy[t], b.wiz[t],  b.wjx[t],
                       b.wjy[t], b.wjz[t], b.hx[t],  b.hy[t],  b.hz[t]};
    const HertzMindlinConstants c{b.k_force[t], b.k_stiffness[t], b.k_damping[t],
                                  b.k_shear[t], b.k_friction[t],  b.k_tdamp[t]};
    law(in, c, dt, b, t);
  }
}

// The touching pairs read where they lie, one material's constants. The inputs are read
// through restrict pointers: without them the compiler must assume a store to b may change
// x, v or w and does not vectorise the loop. The operations are those the packing did
// (x_j - x_i as Vec3's subtraction), so the bits are the same.
[[gnu::always_inline]] inline void evaluate_gathered_loop(
    const int* __restrict touching, const int* __restrict pi, const int* __restrict pj,
    const Vec3* __restrict x, const Vec3* __restrict v, const Vec3* __restrict w,
    const double* __restrict radius, const double* __restrict r_eff, const double* __restrict m_eff,
    const Vec3* __restrict history, const HertzMindlinConstants c, HertzMindlinBatch& __restrict b,
    int count, double dt) {
  for (int t = 0; t < count; ++t) {
    const int k = touching[t], i = pi[k], j = pj[k];
    const LawInputs in{x[j].x - x[i].x, x[j].y - x[i].y, x[j].z - x[i].z, radius[i], radius[j],
                       r_eff[k],        m_eff[k],        v[j].x - v[i].x, v[j].y - v[i].y,
                       v[j].z - v[i].z, w[i].x,          w[i].y,          w[i].z,
                       w[j].x,          w[j].y,          w[j].z,          history[k].x,
                       history[k].y,    history[k].z};
    law(in, c, dt, b, t);
  }
}

[[gnu::always_inline]] inline void evaluate_gathered_inline(const GatheredContacts& g, HertzMindlinBatch& b,
                                                            int count, double dt) {
  evaluate_gathered_loop(g.touching, g.pi, g.pj, g.x, g.v, g.w, g.radius, g.r_eff, g.m_eff, g.history,
                         g.constants, b, count, dt);
}

// One variant per instruction set, each an explicit function (issue 34: each can be tested and
// benchmarked on its own; GCC's target_clones hid them behind one load-time choice). The build
// stays portable (no -march): a variant is called only where the CPU has its instructions.
// clang 14 (the sanitized build, fuzz/CMakeLists.txt) compiled an earlier target_clones
// version for AVX-512 alone and died with SIGILL on a CPU without it (2026-12-04), so under
// clang only the portable variant exists.
void evaluate_portable(HertzMindlinBatch& b, int count, double dt) { evaluate_batch(b, count, dt); }
void gathered_portable(const GatheredContacts& g, HertzMindlinBatch& b, int count, double dt) {
  evaluate_gathered_inline(g, b, count, dt);
}
#if !defined(__clang__)
[[gnu::target("avx2")]] void evaluate_avx2(HertzMindlinBatch& b, int count, double dt) {
  evaluate_batch(b, count, dt);
}
[[gnu::target("avx2")]] void gathered_avx2(const GatheredContacts& g, HertzMindlinBatch& b, int count, double dt) {
  evaluate_gathered_inline(g, b, count, dt);
}
[[gnu::target("avx512f")]] void evaluate_avx512(HertzMindlinBatch& b, int count, double dt) {
  evaluate_batch(b, count, dt);
}
// Tuned for Ice Lake: 256-bit vectors and the hardware gathers. With the generic tuning GCC 12
// builds the gathered inputs element by element into 512-bit vectors, which ran 1-9 % slower
// on the whole step (pack_35k, one thread, two alternated rounds, 2026-12-06; docs/dem.md).
[[gnu::target("avx512f,tune=icelake-server")]] void gathered_avx512(const GatheredContacts& g, HertzMindlinBatch& b,
                                                                   int count, double dt) {
  evaluate_gathered_inline(g, b, count, dt);
}
#endif

struct Variant {
  void (*packed)(HertzMindlinBatch&, int, double);
  void (*gathered)(const GatheredContacts&, HertzMindlinBatch&, int, double);
};

Variant variant(BatchKernel k) {
  switch (k) {
#if !defined(__clang__)
    case BatchKernel::avx512: return {evaluate_avx512, gathered_avx512};
    case BatchKernel::avx2: return {evaluate_avx2, gathered_avx2};
#endif
    default: return {evaluate_portable, gathered_portable};
  }
}

// The variant evaluate() and evaluate_gathered() call: the best the CPU has, chosen once, the
// same for every thread.
Variant& chosen() {
  static Variant v = variant(best_batch_kernel());
  return v;
}

}  // namespace

bool batch_kernel_available(BatchKernel k) {
  switch (k) {
    case BatchKernel::portable: return true;
#if !defined(__clang__)
    case BatchKernel::avx2: return __builtin_cpu_supports("avx2");
    case BatchKernel::avx512: return __builtin_cpu_supports("avx512f");
#endif
    default: return false;
  }
}

BatchKernel best_batch_kernel() {
  for (BatchKernel k : {BatchKernel::avx512, BatchKernel::avx2})
    if (batch_kernel_available(k)) return k;
  return BatchKernel::portable;
}

const char* batch_kernel_name(BatchKernel k) {
  switch (k) {
    case BatchKernel::avx512: return "avx512";
    case BatchKernel::avx2: return "avx2";
    default: return "portable";
  }
}

namespace {

Variant available_variant(BatchKernel k, const char* caller) {
  if (!batch_kernel_available(k))
    throw std::invalid_argument(std::string(caller) + ": this CPU (or build) has no " + batch_kernel_name(k) +
                                " variant");
  return variant(k);
}

}  // namespace

void use_batch_kernel(BatchKernel k) { chosen() = available_variant(k, "use_batch_kernel"); }

void evaluate_with(BatchKernel k, HertzMindlinBatch& b, int count, double dt) {
  available_variant(k, "evaluate_with").packed(b, count, dt);
}

void evaluate(HertzMindlinBatch& b, int count, double dt) { chosen().packed(b, count, dt); }

void evaluate_gathered(const GatheredContacts& g, HertzMindlinBatch& b, int count, double dt) {
  chosen().gathered(g, b, count, dt);
}

}  // namespace kolsky::dem
