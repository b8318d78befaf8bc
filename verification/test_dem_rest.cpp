// A specimen at rest must stay at rest (issue 31, item 0; docs/dem.md "A specimen at rest";
// dem/rest_relaxation.hpp). A pre-stressed jammed packing of the reconstructed Song curve
// (N = 2, 6 x 4 mm, the Chapter 4 walls and grain law) is held between fixed walls with no
// load for 200 us, the hold the issue prescribes (longer than the ~40 us in which the
// Chapter 4 N = 2 packing fell apart), once as the run used to start it (packing positions, no
// tangential history) and once after the preparation's relaxation to rest with its contact
// histories carried into the run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "dem/dem_specimen_params.hpp"
#include "dem/packing_walls.hpp"
#include "song_packing.hpp"
#include "test_support.hpp"

namespace kolsky::dem {
namespace {

constexpr double kSeating = 65e3;  // Pa, the Chapter 4 seating stress


// The Chapter 4 scene's specimen at N = 2 in a small cylinder. rolling: the rotational
// factor per ns (Eqs. 4.12-4.14): the printed 0.99999975 leaves rotation nearly free, 0 locks it.
DemSpecimenParams chapter4_like(bool rest, double rolling) {
  DemSpecimenParams d;
  d.packing = testing::song_jammed(2.0, 0.006, 0.004, 7);  // 1,460 grains
  d.packing.jam_mass_scaling = true;  // as the Chapter 4 scenes (specimen.packing_density_scaling)
  d.packing.jam_steps_per_stage = kJamScaledStepsPerStage;
  d.packing.initial_stress = kSeating;
  d.packing.prestress_wall_normal_stiffness = 2.6e6;  // Table 4.1 walls
  d.packing.prestress_wall_shear_stiffness = 1.6e6;
  d.contact = HertzMindlinParams{0.5, 1.0};            // Table 4.1: mu 0.5, undamped
  d.options.rolling.factor_per_reference_step = rolling;
  if (rest) d.rest = RestRelaxationParams{};
  return d;
}

struct Reading {
  double wall_stress, kinetic, elastic, load_bearing_z;
};

Reading read(const DemSpecimen& s) {
  const DemSystem& sys = s.system();
  const double r = std::sqrt(s.area() / std::numbers::pi);  // tube radius
  const DemEnergy e = sys.energy();
  const double z = coordination_without_rattlers(sys.particles(), 2 * r, s.length()).first;
  // The specimen adds its front and back planes (0, 1) and then the tube (cylinder 0).
  return {wall_mean_stress(sys, r, s.length()), e.kinetic, e.elastic, z};
}

// Steps the specimen with its walls fixed for 200 us (the hold the issue prescribes, five
// times the ~40 us in which the Chapter 4 N = 2 packing fell apart); readings at the start and
// every 50 us.
std::vector<Reading> hold_at_rest(DemSpecimen& s) {
  DemSystem& sys = s.coupled_system();
  const double dt = kDemStepFraction * sys.stable_dt();
  sys.compute_forces();
  std::vector<Reading> out{read(s)};
  const int steps = static_cast<int>(std::ceil(200e-6 / dt));
  const int every = static_cast<int>(std::ceil(50e-6 / dt));
  for (int k = 1; k <= steps; ++k) {
    sys.step(dt);
    if (k % every == 0 || k == steps) out.push_back(read(s));
  }
  return out;
}

// The relaxed specimen with rotation restrained, built once (~8 s); tests copy it.
const DemSpecimen& relaxed_locked() {
  static const DemSpecimen s = make_dem_specimen(chapter4_like(true, 0.0));
  return s;
}

// Rotation restrained (k = 0): the relaxed network carries most of the seating stress, and
// held at rest it keeps it.
TEST(DemRest, RelaxedNetworkWithRotationRestrainedStaysAtRest) {
  DemSpecimen s = relaxed_locked();
  ASSERT_TRUE(s.rest_relaxation().has_value());
  const RestRelaxationOutcome& o = *s.rest_relaxation();
  EXPECT_TRUE(o.converged) << o.steps << " steps, KE/elastic " << o.kinetic_to_elastic;
  const std::vector<Reading> r = hold_at_rest(s);
  const Reading& a = r.front();
  // Measured 55.6 kPa of the 65 kPa seating after the relaxation (the network settles by
  // sliding as its friction is mobilised under the run's law); 0.5: a network, not a gas.
  ASSERT_GT(a.wall_stress, 0.5 * kSeating);
  ASSERT_GT(a.load_bearing_z, 3.0);  // isostatic is 2 with rotation locked, 4 with it free
  for (const Reading& q : r) {
    // 5 %: measured -2.7 % over 200 us (the creep of contacts at the Coulomb limit, which a
    // static equilibrium of a frictional law may keep); a falling network loses 20 % of its
    // stress in the first 10 us (UnrelaxedSpecimenFallsApartAtRest).
    EXPECT_NEAR(q.wall_stress / a.wall_stress, 1.0, 0.05);
    EXPECT_NEAR(q.load_bearing_z / a.load_bearing_z, 1.0, 0.05);
    // The relaxation stops at KE < 1e-6 of the elastic energy (RestRelaxationParams); 1e-5
    // leaves a factor of 10 for what the released network creeps (measured 3e-6).
    EXPECT_LT(q.kinetic, 1e-5 * a.elastic);
  }
}

// The carry of the contact histories is what holds it: the same relaxed positions started
// without their tangential histories (every contact's friction at zero, as runs used to start)
// are no equilibrium of the law.
TEST(DemRest, RelaxedPositionsWithoutTheirHistoriesAreNoEquilibrium) {
  DemSpecimen held = relaxed_locked();
  DemSpecimenParams d = chapter4_like(false, 0.0);
  SpecimenWalls w = d.walls;
  w.length = d.packing.length;
  w.radius = 0.5 * d.packing.diameter;
  std::vector<Material> m{d.packing.material};
  DemSpecimen bare(held.system().particles(), m, make_contact_law(m, d.contact), w, d.options);
  const std::vector<Reading> with = hold_at_rest(held), without = hold_at_rest(bare);
  ASSERT_EQ(with.size(), without.size());
  // At rest the kinetic energy stays below 1e-5 of the elastic energy (above); released
  // without histories the grains move: at least 100x more kinetic energy at some reading.
  double most_with = 0, most_without = 0;
  for (std::size_t k = 0; k < with.size(); ++k) {
    most_with = std::max(most_with, with[k].kinetic);
    most_without = std::max(most_without, without[k].kinetic);
  }
  EXPECT_GT(most_without, 100 * most_with);
}

// The defect the relaxation removes, the witness that the tests above can fail: the packing
// started as the Chapter 4 runs started it (packing positions, no tangential history, the
// printed k = 0.99999975 per ns: rotation nearly free) loses its wall stress within 200 us at
// rest. (Whether the printed reading can hold a network at all, relaxed or not, is measured on
// the Chapter 4 specimens themselves: reproductions/chapter4/README.md, "A specimen at rest";
// in a cylinder this small the walls slow the collapse to hundreds of us.)
TEST(DemRest, UnrelaxedSpecimenFallsApartAtRest) {
  DemSpecimen s = make_dem_specimen(chapter4_like(false, 0.99999975));
  EXPECT_FALSE(s.rest_relaxation().has_value());
  const std::vector<Reading> r = hold_at_rest(s);
  const Reading &a = r.front(), &b = r.back();
  EXPECT_GT(a.wall_stress, 0.5 * kSeating);
  EXPECT_LT(b.wall_stress, 0.1 * a.wall_stress);
  EXPECT_GT(b.kinetic, 1e-3 * a.elastic);  // a gas, not a rest
}

TEST(DemRest, RelaxationIsDeterministicAndRefusesBadParameters) {
  const DemSpecimen& a = relaxed_locked();
  // Rebuilt with a progress observer: the relaxation reports as the preparation's last phase,
  // "relax", and observing changes nothing.
  DemSpecimenParams observed = chapter4_like(true, 0.0);
  std::vector<std::string> phases;
  observed.packing.on_progress = [&](const PackingProgress& q) {
    if (phases.empty() || phases.back() != q.phase) phases.push_back(q.phase);
  };
  DemSpecimen b = make_dem_specimen(observed);
  ASSERT_FALSE(phases.empty());
  EXPECT_EQ(phases.back(), "relax");
  const Particles &pa = a.system().particles(), &pb = b.system().particles();
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i) {
    ASSERT_EQ(pa.x[i].x, pb.x[i].x);
    ASSERT_EQ(pa.x[i].z, pb.x[i].z);
  }
  for (auto bad : {RestRelaxationParams{0.0}, RestRelaxationParams{1e-6, 0},
                   RestRelaxationParams{1e-6, 200, 0}, RestRelaxationParams{1e-6, 200, 100, 1.5}}) {
    DemSpecimenParams d = chapter4_like(false, 0.0);
    d.rest = bad;
    EXPECT_THROW(make_dem_specimen(d), InputError);
  }
  // A compliant tube's displacement is not carried into the run: refused, before packing.
  DemSpecimenParams compliant = chapter4_like(true, 0.0);
  compliant.walls.tube_compliance = TubeCompliance{};
  EXPECT_EQ(testing::input_error([&] { make_dem_specimen(compliant); }).path(), "dem.rest");
}

}  // namespace
}  // namespace kolsky::dem
