// Particle snapshots and their XDMF description (see snapshots.hpp).
#include "io/snapshots.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "io/xml_escape.hpp"

namespace kolsky::io {

namespace fs = std::filesystem;

std::pair<std::string, std::string> snapshot_paths(const std::string& run_output) {
  fs::path p(run_output);
  const fs::path stem = p.parent_path() / p.stem();
  return {stem.string() + ".particles.h5", stem.string() + ".xmf"};
}

namespace {

std::string data_item(const std::string& h5_name, std::size_t k, const char* set,
                      std::size_t n, int cols) {
  const std::string dims = std::to_string(n) + (cols > 1 ? " " + std::to_string(cols) : "");
  return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"Float\" Precision=\"8\" "
         "Format=\"HDF\">" + h5_name + ":/snapshots/" + std::to_string(k) + "/" + set +
         "</DataItem>";
}

}  // namespace

std::string xdmf_text(const std::string& h5_name, const std::vector<SnapshotInfo>& snaps) {
  const std::string h5 = xml_escape(h5_name);
  std::string x =
      "<?xml version=\"1.0\" ?>\n"
      "<Xdmf Version=\"3.0\">\n"
      " <Domain>\n"
      "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  char time[40];
  for (std::size_t k = 0; k < snaps.size(); ++k) {
    const std::size_t n = snaps[k].count;
    std::snprintf(time, sizeof time, "%.17g", snaps[k].time);
    x += "   <Grid Name=\"step_" + std::to_string(snaps[k].step) + "\" GridType=\"Uniform\">\n";
    x += "    <Time Value=\"" + std::string(time) + "\"/>\n";
    x += "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + std::to_string(n) +
         "\" NodesPerElement=\"1\"/>\n";
    x += "    <Geometry GeometryType=\"XYZ\">" + data_item(h5, k, "position", n, 3) +
         "</Geometry>\n";
    x += "    <Attribute Name=\"radius\" AttributeType=\"Scalar\" Center=\"Node\">" +
         data_item(h5, k, "radius", n, 1) + "</Attribute>\n";
    x += "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">" +
         data_item(h5, k, "velocity", n, 3) + "</Attribute>\n";
    x += "    <Attribute Name=\"force\" AttributeType=\"Vector\" Center=\"Node\">" +
         data_item(h5, k, "force", n, 3) + "</Attribute>\n";
    x += "   </Grid>\n";
  }
  x += "  </Grid>\n </Domain>\n</Xdmf>\n";
  return x;
}

SnapshotWriter::SnapshotWriter(std::string h5_path, std::string xmf_path)
    : h5_path_(std::move(h5_path)), xmf_path_(std::move(xmf_path)), tmp_(temporary_name(h5_path_)) {
  h5::silence();
  try {
    file_ = h5::create_file(tmp_);
    group_ = h5::create_group(file_.get(), "snapshots");
  } catch (const std::exception& e) {
    group_ = h5::Handle();
    file_ = h5::Handle();
    std::remove(tmp_.c_str());
    throw std::runtime_error("cannot write particle snapshots " + h5_path_ + ": " + e.what());
  }
}

SnapshotWriter::~SnapshotWriter() {
  if (finished_) return;
  group_ = h5::Handle();  // close before removing
  file_ = h5::Handle();
  std::remove(tmp_.c_str());
}

void SnapshotWriter::add(long step, double t, const dem::Particles& p) {
  static_assert(sizeof(dem::Vec3) == 3 * sizeof(double), "Vec3 arrays are n x 3 doubles");
  const std::size_t n = p.size();
  try {
    h5::Handle g = h5::create_group(group_.get(), std::to_string(snaps_.size()));
    h5::write_doubles(g.get(), "position", n ? &p.x[0].x : nullptr, n, 3);
    h5::write_doubles(g.get(), "radius", p.radius);
    h5::write_doubles(g.get(), "velocity", n ? &p.v[0].x : nullptr, n, 3);
    h5::write_doubles(g.get(), "force", n ? &p.f[0].x : nullptr, n, 3);
    h5::write_attr(g.get(), "time", t);
    h5::write_attr(g.get(), "step", static_cast<std::int64_t>(step));
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write particle snapshots " + h5_path_ + ": " + e.what());
  }
  snaps_.push_back({step, t, n});
}

void SnapshotWriter::finish(bool complete) {
  try {
    h5::Handle meta = h5::create_group(file_.get(), "meta");
    h5::write_attr(meta.get(), "complete", std::int64_t{complete ? 1 : 0});
    h5::write_attr(meta.get(), "count", static_cast<std::int64_t>(snaps_.size()));
    meta = h5::Handle();
    group_ = h5::Handle();
    file_.close("close " + tmp_);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write particle snapshots " + h5_path_ + ": " + e.what());
  }
  finished_ = true;
  commit_file(tmp_, h5_path_);
  write_file_atomic(xmf_path_, xdmf_text(fs::path(h5_path_).filename().string(), snaps_));
}

}  // namespace kolsky::io
