// Hertz-Mindlin grain-pair contacts evaluated a batch at a time, for SIMD (docs/dem.md,
// "Performance"). The per-contact kernel HertzMindlinPair::force() branches twice per contact
// (sliding or sticking, the tangential dashpot's Coulomb cap) and the pair loop once more
// (touching or not, ~50/50 and unpredictable in a dense packing); none of these vectorize. Here
// the touching contacts are first listed, then one branch-free loop evaluates the same law over
// all of them, every branch computed and selected per lane, so the compiler can use 4 or 8
// lanes for the roots and divisions that dominate the cost. The loop reads its inputs either
// from a structure of arrays they were packed into (evaluate: any number of materials) or
// where they lie, in the particles' and the pair list's arrays (evaluate_gathered: one
// material, no copy).
// The arithmetic is that of HertzMindlinPair::force() (contact_pieces.hpp) operation for
// operation, in the same order, and the file is compiled without FMA contraction; IEEE
// +, -, *, / and sqrt round the same in any vector width, so the results are bitwise those of
// the per-contact kernel (test_dem_batch.cpp checks this on a busy scene).
#pragma once
#include <vector>

#include "dem/contact_hertz_mindlin.hpp"

namespace kolsky::dem {

/// Constants of one material pair in the form the batch uses; each is the same product the
/// per-contact kernel forms first (left to right), so the results do not change.
struct HertzMindlinConstants {
  double force = 0;      ///< 4/3 E*: F_el = force a delta
  double stiffness = 0;  ///< 2 E*: S_n = stiffness a
  double damping = 0;    ///< 2 sqrt(5/6) beta: c_n = damping sqrt(S_n m*)
  double shear = 0;      ///< 8 G*: k_t = shear a
  double friction = 0;   ///< mu
  double tangential_damping_scale = 0;  ///< c_t / c_n
};

HertzMindlinConstants batch_constants(const HertzMindlinPair& p);
/// batch_constants of every material pair (a, b) of `law`, at index a x n_materials + b.
std::vector<HertzMindlinConstants> hertz_mindlin_table(const HertzMindlin& law);

/// Inputs and outputs of up to kCapacity touching contacts, one array per scalar. Inputs:
/// d = x_j - x_i, radii, the effective radius and mass (r_i r_j / (r_i + r_j), m_i m_j /
/// (m_i + m_j), formed with these expressions), dv = v_j - v_i, both spins, the history, the
/// constants.
/// Outputs: the force on i, the torques on i and j, the dissipated and stored energies and the
/// updated history (written over the input history).
struct HertzMindlinBatch {
  static constexpr int kCapacity = 128;
  template <class T> using Lane = T[kCapacity];
  alignas(64) Lane<double> dx, dy, dz, ri, rj, r_eff, m_eff, dvx, dvy, dvz;
  alignas(64) Lane<double> wix, wiy, wiz, wjx, wjy, wjz, hx, hy, hz;
  alignas(64) Lane<double> k_force, k_stiffness, k_damping, k_shear, k_friction, k_tdamp;
  alignas(64) Lane<double> fx, fy, fz, tix, tiy, tiz, tjx, tjy, tjz, dissipated, elastic;
};

/// Evaluates contacts [0, count) of b (count <= kCapacity) over the step dt (s), with the
/// instruction-set variant in use (best_batch_kernel() unless use_batch_kernel chose another).
void evaluate(HertzMindlinBatch& b, int count, double dt);

/// The touching contacts of a pair list where they lie, for evaluate_gathered(): contact t is
/// listed pair k = touching[t] of grains i = pi[k], j = pj[k]; one material pair's constants.
struct GatheredContacts {
  const int *touching, *pi, *pj;
  const Vec3 *x, *v, *w;                  ///< the grains' positions, velocities, spins
  const double* radius;                   ///< per grain
  const double *r_eff, *m_eff;            ///< per listed pair (ContactNetwork::pair_r_eff, pair_m_eff)
  const Vec3* history;                    ///< per listed pair
  HertzMindlinConstants constants;
};

/// evaluate() for `count` contacts read where they lie instead of packed into b's input lanes:
/// the outputs and the updated history go to b's output and history lanes, with the same bits
/// (the law is one source; the inputs are formed with the same operations as the packing).
/// Saves the copy into the batch (docs/dem.md, "Performance"). The same variant as evaluate().
void evaluate_gathered(const GatheredContacts& g, HertzMindlinBatch& b, int count, double dt);

/// The instruction-set variants of evaluate(): one source, compiled three times (without FMA
/// contraction, so every variant gives the same bits; test_dem_batch.cpp checks it).
enum class BatchKernel { portable, avx2, avx512 };
/// Whether this CPU and build have the variant (portable always; none but portable in a clang
/// build).
bool batch_kernel_available(BatchKernel k);
/// The widest available variant: what evaluate() uses unless told otherwise.
BatchKernel best_batch_kernel();
const char* batch_kernel_name(BatchKernel k);  ///< "portable", "avx2", "avx512"
/// Makes evaluate() use variant k from now on, process-wide (benchmarks that measure each one).
/// Throws std::invalid_argument where k is not available. Not while a force evaluation runs.
void use_batch_kernel(BatchKernel k);
/// Evaluates with variant k (std::invalid_argument where it is not available).
void evaluate_with(BatchKernel k, HertzMindlinBatch& b, int count, double dt);

}  // namespace kolsky::dem
