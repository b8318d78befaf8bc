// Checkpoint/restart of the simulated SHPB test through the checkpoint file (io/checkpoint_hdf5):
// a run interrupted at step T, written to HDF5, read back and resumed in a freshly built
// simulation, must produce bitwise the probes (and, for DEM, the final grain state) of the
// uninterrupted run: characteristic bars with an elastic column, sphere-chain bars, and a DEM
// specimen (~250 grains with friction). A negative control (DEM histories dropped) must differ,
// so the comparison can fail. Misfitting checkpoints are refused as bad input.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "io/checkpoint_hdf5.hpp"
#include "io/hdf5_run.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"
#include "test_support.hpp"

namespace kolsky {
namespace {

using nlohmann::json;

json column_scene(const std::string& bars_kind) {
  return {{"bars", {{"kind", bars_kind},
                    {"incident", {{"length", 0.6}, {"gauges", {0.3}}}},
                    {"transmission", {{"length", 0.4}, {"gauges", {0.2}}}}}},
          {"pulse", {{"kind", "trapezoid"}, {"amplitude", 50e6}, {"rise_time", 20e-6},
                     {"duration", 100e-6}, {"fall_time", 20e-6}}},
          {"specimen", {{"model", "compaction"}, {"loading_curve", "curve.csv"},
                        {"unloading_modulus", 2e9}, {"n_elements", 20}}},
          {"time", {{"end", 300e-6}}}};
}

// A loose Song-curve packing (upscaled x5, ~250 grains) between short characteristic bars; the
// packing starts with small overlaps, so frictional contacts (with histories) exist throughout.
json dem_scene() {
  return {{"bars", {{"incident", {{"length", 0.6}, {"gauges", {0.3}}}},
                    {"transmission", {{"length", 0.4}, {"gauges", {0.2}}}}}},
          {"pulse", {{"kind", "trapezoid"}, {"amplitude", 20e6}, {"rise_time", 40e-6},
                     {"duration", 200e-6}, {"fall_time", 40e-6}}},
          {"specimen", {{"model", "dem"},
                        {"grain_size_curve", "data/digitized/chapter4/song2009_psd_reconstructed.csv"},
                        {"upscale", 5.0}, {"seed", 7}, {"length", 0.006}, {"diameter", 0.008},
                        {"restitution", 0.5}, {"rolling_factor", 0.99999975}}},
          {"time", {{"end", 200e-6}}},
          {"output", {{"interval", 2e-6}}}};
}

struct IoRestart : ::testing::Test {
  testing::TempDir dir{"kolsky_test_io_restart"};
  scene::Scene parse(const json& j) {
    // The compaction curve lives next to the scene (relative paths resolve against base_dir);
    // the DEM grain-size curve is a path relative to the source tree.
    std::ofstream(dir.file("curve.csv")) << "strain,stress_pa\n0,0\n0.05,20e6\n0.2,200e6\n";
    const bool dem = j["specimen"]["model"] == "dem";
    return scene::parse_scene(j, "restart_test", dem ? KOLSKY_SOURCE_DIR : dir.str());
  }
  // Runs to step `at`, writes the checkpoint there, reads it back.
  io::Checkpoint checkpoint_at(const scene::Scene& sc, long at) {
    shpb::SimulatedShpb sim(sc.spec);
    shpb::RunControl c;
    c.checkpoint_every = at;
    bool written = false;
    c.checkpoint = [&](const shpb::ShpbState& s) {
      if (written) return;
      io::write_checkpoint_hdf5(dir.file("ck.h5"), {{{"scene", sc.resolved}}, s});
      written = true;
    };
    sim.run(nullptr, c);
    EXPECT_TRUE(written);
    return io::read_checkpoint_hdf5(dir.file("ck.h5"));
  }
};

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void expect_same_probes(const shpb::RunResult& a, const shpb::RunResult& b) {
  ASSERT_EQ(a.probes.size(), b.probes.size());
  EXPECT_TRUE(same_bits(a.t, b.t));
  EXPECT_EQ(a.steps, b.steps);
  for (std::size_t k = 0; k < a.probes.size(); ++k)
    EXPECT_TRUE(same_bits(a.probes[k].value, b.probes[k].value)) << a.probes[k].name;
}

TEST_F(IoRestart, ColumnBetweenCharacteristicAndSphereChainBars) {
  for (const char* kind : {"characteristic", "sphere_chain"}) {
    SCOPED_TRACE(kind);
    const scene::Scene sc = parse(column_scene(kind));
    shpb::SimulatedShpb whole(sc.spec);
    const shpb::RunResult full = whole.run();
    ASSERT_TRUE(full.complete) << full.failure;
    const long at = whole.schedule().n_steps / 2 + 7;  // not on a sample: resumes mid-interval
    const io::Checkpoint ck = checkpoint_at(sc, at);
    EXPECT_EQ(ck.state.next_step, at);
    shpb::SimulatedShpb resumed(sc.spec);
    shpb::RunControl c;
    c.resume = &ck.state;
    expect_same_probes(full, resumed.run(nullptr, c));
  }
}

TEST_F(IoRestart, DemSpecimenContinuesBitwise) {
  const scene::Scene sc = parse(dem_scene());
  shpb::SimulatedShpb whole(sc.spec);
  const shpb::RunResult full = whole.run();
  ASSERT_TRUE(full.complete) << full.failure;
  const long at = 2 * whole.schedule().n_steps / 3;
  const io::Checkpoint ck = checkpoint_at(sc, at);
  const auto& dem_state = std::get<dem::DemSpecimenState>(ck.state.specimen).system;
  EXPECT_GT(dem_state.pair_history.size(), 20u);  // frictional contacts carried in the file
  EXPECT_GT(full.probe("grain_contacts").value.back(), 20.0);

  shpb::SimulatedShpb resumed(sc.spec);
  shpb::RunControl c;
  c.resume = &ck.state;
  const shpb::RunResult cont = resumed.run(nullptr, c);
  expect_same_probes(full, cont);
  const auto& p = std::get<dem::DemSpecimen>(whole.specimen()).system().particles();
  const auto& q = std::get<dem::DemSpecimen>(resumed.specimen()).system().particles();
  const std::size_t bytes = p.size() * sizeof(dem::Vec3);
  ASSERT_EQ(p.size(), q.size());
  EXPECT_EQ(std::memcmp(p.x.data(), q.x.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(p.v.data(), q.v.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(p.omega.data(), q.omega.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(p.f.data(), q.f.data(), bytes), 0);

  // Negative control: the same restart without the tangential histories drifts away.
  shpb::ShpbState forgetful = ck.state;
  auto& d = std::get<dem::DemSpecimenState>(forgetful.specimen).system;
  d.pair_i.clear();
  d.pair_j.clear();
  d.pair_history.clear();
  shpb::SimulatedShpb other(sc.spec);
  c.resume = &forgetful;
  const shpb::RunResult off = other.run(nullptr, c);
  EXPECT_FALSE(same_bits(off.probe("stress_front").value, full.probe("stress_front").value));
}

TEST_F(IoRestart, RefusesMisfitsAsBadInput) {
  const scene::Scene column = parse(column_scene("characteristic"));
  const io::Checkpoint ck = checkpoint_at(column, 100);
  shpb::SimulatedShpb chain(parse(column_scene("sphere_chain")).spec);
  shpb::RunControl c;
  c.resume = &ck.state;
  try {
    chain.run(nullptr, c);
    ADD_FAILURE() << "a characteristic-bar checkpoint was accepted by sphere-chain bars";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "restart");
  }
  std::ofstream(dir.file("not.h5")) << "plain text";
  try {
    io::read_checkpoint_hdf5(dir.file("not.h5"));
    ADD_FAILURE() << "a text file was read as a checkpoint";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), dir.file("not.h5"));
  }
  io::write_run_hdf5(dir.file("run.h5"), {});  // an HDF5 file, but no checkpoint
  EXPECT_THROW(io::read_checkpoint_hdf5(dir.file("run.h5")), InputError);

  // The fe specimen has no checkpoint state: refused before the first step.
  json fe = column_scene("characteristic");
  fe["specimen"] = {{"model", "fe"}, {"loading_curve", "curve.csv"}, {"unloading_modulus", 2e9},
                    {"n_radial", 2}, {"n_axial", 2}};
  shpb::SimulatedShpb fe_sim(parse(fe).spec);
  EXPECT_FALSE(fe_sim.can_checkpoint());
  shpb::RunControl ck_fe;
  ck_fe.checkpoint_every = 10;
  ck_fe.checkpoint = [](const shpb::ShpbState&) {};
  try {
    fe_sim.run(nullptr, ck_fe);
    ADD_FAILURE() << "an fe run accepted a checkpoint request";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "specimen.model");
  }
}

}  // namespace
}  // namespace kolsky
