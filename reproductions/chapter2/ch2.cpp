#include "chapter2/ch2.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/errors.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"

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

CaseResult run_case(const BaseScene& base, const CaseSpec& c) {
  CaseResult out;
  const auto start = std::chrono::steady_clock::now();
  try {
    auto j = base.json;
    auto& s = j["specimen"];
    s["tube_youngs_modulus"] = c.tube.youngs_modulus;
    s["tube_poisson_ratio"] = c.tube.poisson_ratio;
    s["tube_density"] = c.tube.density;
    s["tube_thickness"] = c.tube.thickness;
    s["friction_faces"] = c.friction;
    s["friction_tube"] = c.friction;
    if (c.length > 0) s["length"] = c.length;
    if (c.n_radial > 0) s["n_radial"] = c.n_radial;
    if (c.n_axial > 0) s["n_axial"] = c.n_axial;
    if (!c.bars.empty()) j["bars"]["kind"] = c.bars;
    if (c.bar_mesh_radial > 0) j["bars"]["mesh_radial"] = c.bar_mesh_radial;
    if (c.bar_element_length > 0) j["bars"]["element_length"] = c.bar_element_length;
    if (c.end_time > 0) j["time"]["end"] = c.end_time;
    if (!c.pulse_file.empty()) j["pulse"]["file"] = c.pulse_file;
    j["pulse"]["scale"] = c.pulse_scale;
    auto sc = scene::parse_scene(j, base.path, base.dir);
    auto& fe_params = std::get<fe::FeSpecimenParams>(sc.spec.specimen);
    auto& mat = std::get<fe::PseudoTensorModeI>(fe_params.material);
    mat.eos.loading = c.eos;
    mat.eos.loading.extrapolate = true;
    mat.eos.unloading_bulk_modulus = unloading_modulus_for(c.eos);
    mat.validate("chapter2.eos");
    shpb::SimulatedShpb sim(sc.spec);
    const auto run = sim.run();
    out.dt = run.dt;
    out.steps = run.steps;
    if (!run.complete) {
      out.failure = run.failure;
    } else {
      const auto setup = sim.analysis_setup();
      const auto waves =
          run.face_waves(setup.incident.youngs_modulus, setup.transmission.youngs_modulus);
      out.h = shpb::analyze(waves, setup);
      out.ok = true;
    }
  } catch (const std::exception& e) {
    out.failure = e.what();
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
  std::ofstream f(path);
  f << header << "\n";
  f.precision(10);
  for (size_t k = 0; k < t.x.size(); ++k) f << t.x[k] << "," << t.y[k] << "\n";
  if (!f) throw std::runtime_error("cannot write " + path);
}

std::vector<double> scaled(const std::vector<double>& v, double f) {
  std::vector<double> out(v.size());
  std::transform(v.begin(), v.end(), out.begin(), [f](double x) { return x * f; });
  return out;
}

}  // namespace kolsky::ch2
