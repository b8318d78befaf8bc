#include "chapter2/ch2.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "core/hash.hpp"
#include "harness/case_pipeline.hpp"

namespace kolsky::ch2 {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  return nlohmann::json::parse(f);
}


double unloading_modulus_for(const Table1D& t) {
  double steepest = 0;
  for (size_t k = 1; k < t.x.size(); ++k)
    steepest = std::max(steepest, (t.y[k] - t.y[k - 1]) / (t.x[k] - t.x[k - 1]));
  return std::max(1e9, 1.2 * steepest);
}

namespace {

/// A table as CSV text, each value in the shortest form that reads back exactly (to_chars),
/// so that a reader gets the table's exact values.
std::string table_csv_text(const Table1D& t, const std::string& header) {
  std::string text = header + "\n";
  char buf[32];
  for (size_t k = 0; k < t.x.size(); ++k) {
    text.append(buf, std::to_chars(buf, buf + sizeof buf, t.x[k]).ptr);
    text += ',';
    text.append(buf, std::to_chars(buf, buf + sizeof buf, t.y[k]).ptr);
    text += '\n';
  }
  return text;
}

/// The table as the scene's loading_curve CSV in `dir`, named by its content (FNV-1a of the
/// text): written once, so that the same table is the same file and the case's content key
/// (which takes a file by its path) names the table too.
std::string eos_table_file(const std::string& dir, const Table1D& t) {
  const std::string text = table_csv_text(t, "strain,stress_pa");
  char name[32];
  std::snprintf(name, sizeof name, "eos_%016llx.csv", static_cast<unsigned long long>(fnv1a_64(text)));
  const std::string path = std::filesystem::absolute(std::filesystem::path(dir) / name).string();
  if (!std::filesystem::exists(path)) {
    std::filesystem::create_directories(dir);
    write_file_atomic(path, text);
  }
  return path;
}

}  // namespace

CaseResult run_case(const BaseScene& base, const CaseSpec& c) {
  harness::Case hc;
  hc.label = c.label;
  hc.scene_path = base.path;
  hc.scene = base.json;
  auto set = [&hc](const std::string& key, nlohmann::json value) { hc.changes.push_back({key, std::move(value)}); };
  set("specimen.tube_youngs_modulus", c.tube.youngs_modulus);
  set("specimen.tube_poisson_ratio", c.tube.poisson_ratio);
  set("specimen.tube_density", c.tube.density);
  set("specimen.tube_thickness", c.tube.thickness);
  set("specimen.friction_faces", c.friction);
  set("specimen.friction_tube", c.friction);
  if (c.length > 0) set("specimen.length", c.length);
  if (c.n_radial > 0) set("specimen.n_radial", c.n_radial);
  if (c.n_axial > 0) set("specimen.n_axial", c.n_axial);
  if (!c.bars.empty()) set("bars.kind", c.bars);
  if (c.bar_mesh_radial > 0) set("bars.mesh_radial", c.bar_mesh_radial);
  if (c.bar_element_length > 0) set("bars.element_length", c.bar_element_length);
  if (c.end_time > 0) set("time.end", c.end_time);
  if (!c.pulse_file.empty()) set("pulse.file", c.pulse_file);
  set("pulse.scale", c.pulse_scale);
  CaseResult out;
  try {
    set("specimen.loading_curve", eos_table_file(base.table_dir, c.eos));
    set("specimen.unloading_modulus", unloading_modulus_for(c.eos));
  } catch (const std::exception& e) {
    out.failure = e.what();
    return out;
  }
  const harness::CaseOutputs o = harness::run_case(hc);
  out.ok = o.ok && o.analysis_failure.empty();
  out.failure = o.ok ? o.analysis_failure : o.failure;
  out.h = o.history;
  out.dt = o.run.dt;
  out.steps = o.run.steps;
  out.wall_s = o.wall_s;
  return out;
}

double loading_slope(const shpb::SpecimenHistory& h, double e0, double e1, double t_end) {
  const long n = static_cast<long>(h.t.size());
  long peak = 0;
  for (long k = 0; k < n && h.t[k] <= t_end; ++k)
    if (h.strain[k] > h.strain[peak]) peak = k;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  long m = 0;
  for (long k = 0; k <= peak; ++k) {
    const double x = h.strain[k], y = h.stress_back[k];
    if (x < e0 || x > e1 || !std::isfinite(y)) continue;
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
  }
  if (m < 3) return kNaN;
  const double den = m * sxx - sx * sx;
  return den > 0 ? (m * sxy - sx * sy) / den : kNaN;
}

double mean_over(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1) {
  double sum = 0;
  long m = 0;
  for (size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0 && t[k] <= t1 && std::isfinite(v[k])) sum += v[k], ++m;
  return m > 0 ? sum / static_cast<double>(m) : kNaN;
}

double equilibrium_time(const shpb::SpecimenHistory& h, double threshold, double t_end) {
  long k = static_cast<long>(std::upper_bound(h.t.begin(), h.t.end(), t_end) - h.t.begin()) - 1;
  if (k < 0 || !(h.alpha[k] < threshold)) return kNaN;
  while (k > 0 && h.alpha[k - 1] < threshold) --k;  // NaN compares false: ends the run
  return h.t[k];
}

double at_strain(const shpb::SpecimenHistory& h, const std::vector<double>& v, double strain) {
  for (size_t k = 0; k < h.strain.size(); ++k)
    if (h.strain[k] >= strain) return v[k];
  return kNaN;
}

double reference_value(const nlohmann::json& targets, const std::string& id) {
  if (targets.contains("targets")) {
    for (const auto& t : targets.at("targets"))
      if (t.at("id") == id) return t.at("reference").at("value").get<double>();
  } else {
    for (const auto& v : targets.at("values"))
      if (v.at("id") == id) return v.at("value").get<double>();
  }
  throw std::runtime_error("no reference value for " + id);
}

Table1D read_table_csv(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  Table1D t;
  std::string line;
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream is(line);
    double x, y;
    if (is >> x >> y) t.x.push_back(x), t.y.push_back(y);
  }
  return t;
}

void write_table_csv(const std::string& path, const Table1D& t, const std::string& header) {
  write_file_atomic(path, table_csv_text(t, header));
  // Read back: a table written for reuse must give its exact values (a 10-digit table did not).
  const Table1D back = read_table_csv(path);
  if (back.x != t.x || back.y != t.y) throw std::runtime_error(path + ": the table read back differs from the one written");
}

std::vector<double> scaled(const std::vector<double>& v, double f) {
  std::vector<double> out(v.size());
  std::transform(v.begin(), v.end(), out.begin(), [f](double x) { return x * f; });
  return out;
}

}  // namespace kolsky::ch2
