// The packing cache's file store (see packing_files.hpp).
#include "io/packing_files.hpp"

#include <cstring>
#include <filesystem>
#include <cstdint>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>

#include "core/atomic_file.hpp"

namespace kolsky::io {

namespace {

namespace fs = std::filesystem;
constexpr char kMagic[8] = {'K', 'P', 'A', 'C', 'K', '0', '0', '2'};
constexpr char kMagic001[8] = {'K', 'P', 'A', 'C', 'K', '0', '0', '1'};

// The PackingResult scalars, in file order.
template <class F>
void for_scalars(dem::PackingResult& r, F&& f) {
  f(r.porosity), f(r.target_porosity), f(r.expected_count), f(r.coordination),
      f(r.coordination_with_walls), f(r.max_overlap), f(r.curve_deviation),
      f(r.curve_deviation_bound), f(r.kinetic_energy), f(r.coordination_no_rattlers),
      f(r.rattler_fraction), f(r.mean_stress), f(r.mean_stress_hertz), f(r.packing_friction);
}

void write_file(const std::string& path, std::uint64_t key, dem::PackingResult r) {
  // The pid (temporary_name) keeps processes apart, the draw threads of one process.
  const std::string tmp = temporary_name(path) + "." + std::to_string(std::random_device{}());
  {
    std::ofstream f(tmp, std::ios::binary);
    auto put = [&](const auto& v) { f.write(reinterpret_cast<const char*>(&v), sizeof v); };
    f.write(kMagic, sizeof kMagic);
    put(key);
    const std::uint64_t n = r.particles.size();
    put(n);
    const std::int64_t steps = r.steps, stages = r.stages, settled = r.settled;
    put(steps), put(stages), put(settled);
    for_scalars(r, [&](double& v) { put(v); });
    const std::int64_t pre_stages = r.prestress_stages, pre_converged = r.prestress_converged;
    put(r.prestress_scale), put(pre_stages), put(pre_converged);
    const dem::Particles& p = r.particles;
    for (const auto* a : {&p.x, &p.v, &p.omega, &p.f, &p.torque})
      f.write(reinterpret_cast<const char*>(a->data()), static_cast<std::streamsize>(n * sizeof(dem::Vec3)));
    for (const auto* a : {&p.radius, &p.mass, &p.inertia})
      f.write(reinterpret_cast<const char*>(a->data()), static_cast<std::streamsize>(n * sizeof(double)));
    f.write(reinterpret_cast<const char*>(p.material.data()), static_cast<std::streamsize>(n * sizeof(int)));
    if (!f) {
      std::error_code ec;
      fs::remove(tmp, ec);
      return;
    }
  }
  try {
    commit_file(tmp, path);  // atomic within one directory
  } catch (const std::runtime_error&) {
    std::error_code ec;
    fs::remove(tmp, ec);
  }
}

bool read_file(const std::string& path, std::uint64_t key, dem::PackingResult& r) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  auto get = [&](auto& v) { f.read(reinterpret_cast<char*>(&v), sizeof v); };
  char magic[8];
  f.read(magic, sizeof magic);
  std::uint64_t k = 0, n = 0;
  get(k), get(n);
  const bool v2 = std::memcmp(magic, kMagic, sizeof kMagic) == 0;
  const bool v1 = std::memcmp(magic, kMagic001, sizeof kMagic001) == 0;
  if (!f || !(v1 || v2) || k != key || n > (1ull << 32)) return false;
  std::int64_t steps = 0, stages = 0, settled = 0, pre_stages = 0, pre_converged = 0;
  get(steps), get(stages), get(settled);
  for_scalars(r, [&](double& v) { get(v); });
  if (v2) get(r.prestress_scale), get(pre_stages), get(pre_converged);
  r.prestress_stages = static_cast<int>(pre_stages);
  r.prestress_converged = pre_converged != 0;
  dem::Particles& p = r.particles;
  for (auto* a : {&p.x, &p.v, &p.omega, &p.f, &p.torque}) {
    a->resize(n);
    f.read(reinterpret_cast<char*>(a->data()), static_cast<std::streamsize>(n * sizeof(dem::Vec3)));
  }
  for (auto* a : {&p.radius, &p.mass, &p.inertia}) {
    a->resize(n);
    f.read(reinterpret_cast<char*>(a->data()), static_cast<std::streamsize>(n * sizeof(double)));
  }
  p.material.resize(n);
  f.read(reinterpret_cast<char*>(p.material.data()), static_cast<std::streamsize>(n * sizeof(int)));
  if (!f || f.peek() != std::char_traits<char>::eof()) return false;
  r.steps = static_cast<int>(steps);
  r.stages = static_cast<int>(stages);
  r.settled = settled != 0;
  r.count = n;
  return true;
}

}  // namespace

dem::PackingStore packing_files(const std::string& dir) {
  if (dir.empty()) return {};
  const auto path = [dir](const std::string& key) { return (fs::path(dir) / ("packing_" + key + ".bin")).string(); };
  dem::PackingStore s;
  s.name = path;
  s.load = [path](const std::string& key, dem::PackingResult& out) {
    return read_file(path(key), std::stoull(key, nullptr, 16), out);
  };
  s.save = [dir, path](const std::string& key, const dem::PackingResult& r) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (!ec) write_file(path(key), std::stoull(key, nullptr, 16), r);
  };
  return s;
}

}  // namespace kolsky::io
