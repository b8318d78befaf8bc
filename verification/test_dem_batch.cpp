// The batched Hertz-Mindlin kernel (solver/dem/hertz_mindlin_batch.hpp) against the per-contact
// kernel it restructures (DemOptions::batched_hertz_mindlin = false). Tolerance: bitwise. The
// batch performs the same IEEE operations in the same order without FMA contraction, so any
// difference, even in the last bit or the sign of a zero, is a transcription error in one of
// the selects that replace the per-contact branches (sliding, dashpot cap, history rotation).
// Both kernels sweep the owners in the same fixed blocks (DemOptions::owner_block) and add a
// partner's side directly within a block, through its slot across blocks, so every grain's
// sums have the same order in both; the scene uses small blocks so that both paths occur.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "dem/dem_system.hpp"
#include "dem/hertz_mindlin_batch.hpp"
#include "dem_busy_scene.hpp"

namespace kolsky::dem {
namespace {

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Runs the busy scene (friction, damping, a moving plane, a compliant tube, rebuilds) with the
// given law parameters and materials, once per kernel, and compares the full state and the
// energy ledger after every 50 steps.
void expect_kernels_agree(const HertzMindlinParams& hp, const std::vector<Material>& materials) {
  const test::BusyScene scene;
  auto make = [&](bool batched) {
    // The busy scene's grains, enlarged so that each presses on its lattice neighbours: a
    // dense packing, with both sliding and sticking contacts.
    const Particles lattice = test::busy_grains(scene);
    Particles p;
    for (std::size_t i = 0; i < lattice.size(); ++i)
      p.add(lattice.x[i], scene.r * (1.002 + 0.002 * static_cast<double>(i % 3)),
            static_cast<int>(i % materials.size()), materials);
    p.v = lattice.v;
    p.omega = lattice.omega;
    DemOptions opt = test::busy_options();
    opt.batched_hertz_mindlin = batched;
    opt.owner_block = 64;  // ~400 grains: 7 blocks, many pairs across a block boundary
    DemSystem sys(p, materials, HertzMindlin(materials, hp), opt);
    const WallLaw hw = HertzMindlinWall(materials, materials[0], hp);
    sys.add_plane({{0, 0, 0}, {0, 0, 1}, FixedPlane{}, hw});
    sys.add_plane({{0, 0, scene.top()}, {0, 0, -1}, PrescribedPlane{{{0.0}, {10.0}}}, hw});
    CylinderWall tube;  // as test::busy_system: keeps the grains together
    tube.radius = scene.tube_radius;
    tube.law = linear_spring(2.6e6, 1.6e6, 0.3);
    tube.compliance = TubeCompliance{200e9, scene.tube_wall, 8100, scene.top()};
    sys.add_cylinder(tube);
    return sys;
  };
  DemSystem batched = make(true), reference = make(false);
  const double dt = 0.5 * (kDemStepFraction * reference.stable_dt());
  std::size_t touching = 0;
  for (int k = 1; k <= 300; ++k) {
    batched.step(dt);
    reference.step(dt);
    touching = std::max(touching, reference.n_contacts());
    if (k % 50 != 0) continue;
    const Particles &a = batched.particles(), &b = reference.particles();
    ASSERT_TRUE(same_bits(a.x, b.x)) << "step " << k;
    ASSERT_TRUE(same_bits(a.v, b.v)) << "step " << k;
    ASSERT_TRUE(same_bits(a.omega, b.omega)) << "step " << k;
    ASSERT_TRUE(same_bits(a.f, b.f)) << "step " << k;
    ASSERT_TRUE(same_bits(a.torque, b.torque)) << "step " << k;
    const DemEnergy ea = batched.energy(), eb = reference.energy();
    EXPECT_TRUE(same_bits(ea.elastic, eb.elastic)) << "step " << k;
    EXPECT_TRUE(same_bits(ea.dissipated, eb.dissipated)) << "step " << k;
    EXPECT_EQ(batched.n_contacts(), reference.n_contacts()) << "step " << k;
  }
  std::printf("  %zu grains, up to %zu touching pairs\n", reference.particles().size(), touching);
  EXPECT_GT(touching, 200u);  // the scene is busy: many contacts, so both branches are taken
  EXPECT_GT(reference.n_rebuilds(), 2u);  // histories carried through rebuilds
  EXPECT_GT(reference.energy().dissipated, 0.0);
}

TEST(DemBatchKernel, MatchesPerContactKernelBitwise) {
  expect_kernels_agree({0.5, 0.5}, test::kBusySand);
}

TEST(DemBatchKernel, MatchesWithoutDampingAndWithLowFriction) {
  // Undamped (c_t = 0: the sticking branch adds nothing) and mostly sliding (mu = 0.05).
  expect_kernels_agree({0.05, 1.0}, test::kBusySand);
}

TEST(DemBatchKernel, MatchesWithTwoMaterials) {
  // Alternating materials: the constants come from the material-pair table per contact.
  const std::vector<Material> two{{78e9, 0.3, 2650}, {20e9, 0.2, 2650}};
  expect_kernels_agree({0.5, 0.3}, two);
}

// Every instruction-set variant of the batch law (issue 34; hertz_mindlin_batch.hpp), both of its
// input paths (packed, and read where they lie), against the per-contact kernel on the same busy
// scene. One source compiled without contraction, so the tolerance is again bitwise, in every
// variant. A variant this CPU or build lacks is skipped (the output says which ran: on the
// 2-core CI machine, portable and AVX2).
TEST(DemBatchKernel, EveryInstructionSetVariantMatchesBitwise) {
  int ran = 0;
  for (BatchKernel k : {BatchKernel::portable, BatchKernel::avx2, BatchKernel::avx512}) {
    if (!batch_kernel_available(k)) {
      std::printf("  %s: not on this CPU or build, skipped\n", batch_kernel_name(k));
      continue;
    }
    std::printf("  %s\n", batch_kernel_name(k));
    use_batch_kernel(k);
    expect_kernels_agree({0.5, 0.5}, test::kBusySand);  // one material: evaluate_gathered
    expect_kernels_agree({0.5, 0.3}, {{78e9, 0.3, 2650}, {20e9, 0.2, 2650}});  // two: evaluate
    ++ran;
  }
  use_batch_kernel(best_batch_kernel());
  EXPECT_GE(ran, 1);
}

TEST(DemBatchKernel, AVariantTheCpuLacksIsRefused) {
  for (BatchKernel k : {BatchKernel::avx2, BatchKernel::avx512})
    if (!batch_kernel_available(k)) {
      EXPECT_THROW(use_batch_kernel(k), std::invalid_argument);
      HertzMindlinBatch b;
      EXPECT_THROW(evaluate_with(k, b, 0, 1e-9), std::invalid_argument);
    }
  EXPECT_TRUE(batch_kernel_available(BatchKernel::portable));
  EXPECT_TRUE(batch_kernel_available(best_batch_kernel()));
}

}  // namespace
}  // namespace kolsky::dem
