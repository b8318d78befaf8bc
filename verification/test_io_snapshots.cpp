// Particle snapshots (io/snapshots): a tiny DEM run through SimulatedShpb's snapshot hook and
// SnapshotWriter, read back with the HDF5 C API (shapes, values, time attributes), and the XDMF
// checked to be well-formed XML whose every DataItem names an existing dataset of the stated
// dimensions. A run that blows up keeps its snapshots marked incomplete; an abandoned writer
// leaves no file.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "io/snapshots.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"
#include "test_support.hpp"

namespace kolsky {
namespace {

struct Captured {
  long step;
  double t;
  dem::Particles p;
};

nlohmann::json tiny_dem_scene() {
  return {{"bars", {{"incident", {{"length", 0.3}, {"gauges", {0.15}}}},
                    {"transmission", {{"length", 0.2}, {"gauges", {0.1}}}}}},
          {"pulse", {{"kind", "half_sine"}, {"amplitude", 10e6}, {"duration", 50e-6}}},
          {"specimen", {{"model", "dem"},
                        {"grain_size_curve", "data/digitized/chapter4/song2009_psd_reconstructed.csv"},
                        {"upscale", 5.0}, {"seed", 7}, {"length", 0.006}, {"diameter", 0.008}}},
          {"time", {{"end", 20e-6}}},
          {"output", {{"snapshot_interval", 5e-6}}}};
}

std::vector<hsize_t> dims_of(hid_t file, const std::string& path) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  std::vector<hsize_t> d(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, d.data(), nullptr);
  H5Sclose(space);
  H5Dclose(set);
  return d;
}

std::vector<double> read_all(hid_t file, const std::string& path, std::size_t n) {
  std::vector<double> v(n);
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(set, 0) << path;
  if (set < 0) return v;
  EXPECT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
  H5Dclose(set);
  return v;
}

double attr_double(hid_t file, const std::string& obj, const char* name) {
  double v = -1;
  const hid_t a = H5Aopen_by_name(file, obj.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(a, 0) << obj << "/" << name;
  if (a >= 0) {
    H5Aread(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a);
  }
  return v;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(IoSnapshots, DemRunWritesReadableSnapshotsAndXdmf) {
  testing::TempDir dir("kolsky_test_io_snapshots");
  const auto sc = scene::parse_scene(tiny_dem_scene(), "snap_test", KOLSKY_SOURCE_DIR);
  shpb::SimulatedShpb sim(sc.spec);
  const auto [h5_path, xmf_path] = io::snapshot_paths(dir.file("run.h5"));
  EXPECT_EQ(h5_path, dir.file("run.particles.h5"));
  EXPECT_EQ(xmf_path, dir.file("run.xmf"));
  std::vector<Captured> seen;
  {
    io::SnapshotWriter w(h5_path, xmf_path);
    shpb::RunControl c;
    c.snapshot_every = std::lround(5e-6 / sim.schedule().dt);
    c.snapshot = [&](long n, double t, const dem::Particles& p) {
      w.add(n, t, p);
      seen.push_back({n, t, p});
    };
    const auto r = sim.run(nullptr, c);
    w.finish(r.complete);
    ASSERT_TRUE(r.complete) << r.failure;
  }
  // Steps 0, k, 2k, ... up to the last step.
  const long k = std::lround(5e-6 / sim.schedule().dt);
  ASSERT_EQ(seen.size(), static_cast<std::size_t>((sim.schedule().n_steps - 1) / k + 1));
  EXPECT_EQ(seen[1].step, k);
  EXPECT_EQ(dir.n_entries(), 2u) << "particle file and XDMF only, no temporary left";

  const hid_t file = H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(attr_double(file, "/meta", "complete"), 1.0);
  for (std::size_t s = 0; s < seen.size(); ++s) {
    const std::string g = "/snapshots/" + std::to_string(s);
    const dem::Particles& p = seen[s].p;
    const hsize_t n = p.size();
    EXPECT_EQ(dims_of(file, g + "/position"), (std::vector<hsize_t>{n, 3}));
    EXPECT_EQ(dims_of(file, g + "/velocity"), (std::vector<hsize_t>{n, 3}));
    EXPECT_EQ(dims_of(file, g + "/force"), (std::vector<hsize_t>{n, 3}));
    EXPECT_EQ(dims_of(file, g + "/radius"), (std::vector<hsize_t>{n}));
    EXPECT_EQ(attr_double(file, g, "time"), seen[s].t);
    const auto x = read_all(file, g + "/position", 3 * n);
    const auto f = read_all(file, g + "/force", 3 * n);
    const auto r = read_all(file, g + "/radius", n);
    for (std::size_t i = 0; i < n; i += 37) {
      EXPECT_EQ(x[3 * i + 2], p.x[i].z);
      EXPECT_EQ(f[3 * i], p.f[i].x);
      EXPECT_EQ(r[i], p.radius[i]);
    }
  }
  // Forces are those of t^n: the packing's small initial overlaps push some grains apart.
  const auto& f0 = seen.front().p.f;
  EXPECT_TRUE(std::any_of(f0.begin(), f0.end(), [](const dem::Vec3& f) { return f.z != 0.0; }));

  // XDMF: balanced tags, one Grid per snapshot in a temporal collection, DataItems that name
  // existing datasets of the stated dimensions in the particle file.
  const std::string xmf = slurp(xmf_path);
  EXPECT_EQ(xmf.rfind("<?xml", 0), 0u);
  const std::regex tag(R"(<(/?)([A-Za-z]+)[^>]*?(/?)>)");
  std::vector<std::string> stack;
  int grids = 0;
  for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), tag); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[2];
    if ((*it)[1] == "/") {
      ASSERT_FALSE(stack.empty()) << "closing " << name << " without opening";
      EXPECT_EQ(stack.back(), name);
      stack.pop_back();
    } else if ((*it)[3] != "/") {
      stack.push_back(name);
      if (name == "Grid") ++grids;
    }
  }
  EXPECT_TRUE(stack.empty()) << "unclosed <" << (stack.empty() ? "" : stack.back()) << ">";
  EXPECT_EQ(grids, static_cast<int>(seen.size()) + 1);  // the collection plus one per snapshot
  EXPECT_NE(xmf.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(xmf.find("TopologyType=\"Polyvertex\""), std::string::npos);
  const std::regex item(R"re(<DataItem Dimensions="([0-9 ]+)"[^>]*>([^<:]+):([^<]+)</DataItem>)re");
  int items = 0;
  for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), item); it != std::sregex_iterator(); ++it) {
    ++items;
    EXPECT_EQ((*it)[2], "run.particles.h5");
    std::vector<hsize_t> want;
    std::istringstream ds((*it)[1].str());
    for (hsize_t d; ds >> d;) want.push_back(d);
    EXPECT_EQ(dims_of(file, (*it)[3]), want) << (*it)[3];
  }
  EXPECT_EQ(items, 4 * static_cast<int>(seen.size()));
  H5Fclose(file);
}

TEST(IoSnapshots, IncompleteRunKeepsSnapshotsAndAnAbandonedWriterLeavesNothing) {
  testing::TempDir dir("kolsky_test_io_snapshots");
  dem::Particles p;
  const std::vector<dem::Material> m{{}};
  p.add({0, 0, 1e-3}, 1e-4, 0, m);
  {
    io::SnapshotWriter w(dir.file("a.particles.h5"), dir.file("a.xmf"));
    w.add(0, 0.0, p);
    w.finish(false);
  }
  const hid_t file = H5Fopen(dir.file("a.particles.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(attr_double(file, "/meta", "complete"), 0.0);
  H5Fclose(file);
  EXPECT_EQ(dir.n_entries(), 2u);
  {
    io::SnapshotWriter w(dir.file("b.particles.h5"), dir.file("b.xmf"));
    w.add(0, 0.0, p);
  }  // destroyed unfinished, as when an exception unwinds the run
  EXPECT_EQ(dir.n_entries(), 2u) << "an unfinished writer must remove its temporary file";
}

TEST(IoSnapshots, FramesWithDifferentParticleCountsEachDescribeTheirOwnGrid) {
  // Breakage changes the count between frames (docs/breakage.md): every XDMF grid must carry its
  // own size, or ParaView reads past the arrays of the smaller frames.
  const std::string x = io::xdmf_text("run.particles.h5", {{0, 0.0, 249}, {100, 1e-6, 756}});
  EXPECT_NE(x.find("NumberOfElements=\"249\""), std::string::npos);
  EXPECT_NE(x.find("NumberOfElements=\"756\""), std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"249 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">run.particles.h5:/snapshots/0/position"),
            std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"756 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">run.particles.h5:/snapshots/1/position"),
            std::string::npos);
}

}  // namespace
}  // namespace kolsky
