// Packing cache (see packing_cache.hpp).
#include "dem/packing_cache.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <type_traits>
#include <vector>

#include "core/hash.hpp"

namespace kolsky::dem {

namespace {

namespace fs = std::filesystem;
// Format 002 adds the pre-stress results after the scalars; 001 files (no pre-stress) are
// still read.
constexpr char kMagic[8] = {'K', 'P', 'A', 'C', 'K', '0', '0', '2'};
constexpr char kMagic001[8] = {'K', 'P', 'A', 'C', 'K', '0', '0', '1'};

struct Hasher {
  // FNV-1a 64 with the basis kolsky's cache keys were made with (core/hash.hpp): a standard
  // basis would only regenerate every cached packing.
  std::uint64_t h = kLegacyIdentityOffset;
  template <class T>
  void add(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    for (unsigned char c : b) h = (h ^ c) * 1099511628211ull;
  }
  void add(const std::vector<double>& v) {
    add(v.size());
    for (double d : v) add(d);
  }
};

// The PackingResult scalars, in file order.
template <class F>
void for_scalars(PackingResult& r, F&& f) {
  f(r.porosity), f(r.target_porosity), f(r.expected_count), f(r.coordination),
      f(r.coordination_with_walls), f(r.max_overlap), f(r.curve_deviation),
      f(r.curve_deviation_bound), f(r.kinetic_energy), f(r.coordination_no_rattlers),
      f(r.rattler_fraction), f(r.mean_stress), f(r.mean_stress_hertz), f(r.packing_friction);
}

void write_file(const std::string& path, std::uint64_t key, PackingResult r) {
  std::random_device rd;
  const std::string tmp = path + ".tmp." + std::to_string(rd());
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
    const Particles& p = r.particles;
    for (const auto* a : {&p.x, &p.v, &p.omega, &p.f, &p.torque})
      f.write(reinterpret_cast<const char*>(a->data()), static_cast<std::streamsize>(n * sizeof(Vec3)));
    for (const auto* a : {&p.radius, &p.mass, &p.inertia})
      f.write(reinterpret_cast<const char*>(a->data()), static_cast<std::streamsize>(n * sizeof(double)));
    f.write(reinterpret_cast<const char*>(p.material.data()), static_cast<std::streamsize>(n * sizeof(int)));
    if (!f) {
      std::error_code ec;
      fs::remove(tmp, ec);
      return;
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);  // atomic on POSIX within one directory
  if (ec) fs::remove(tmp, ec);
}

bool read_file(const std::string& path, std::uint64_t key, PackingResult& r) {
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
  Particles& p = r.particles;
  for (auto* a : {&p.x, &p.v, &p.omega, &p.f, &p.torque}) {
    a->resize(n);
    f.read(reinterpret_cast<char*>(a->data()), static_cast<std::streamsize>(n * sizeof(Vec3)));
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

std::string packing_cache_key(const PackingParams& q) {
  Hasher h;
  h.add(kPackingAlgorithmVersion);
  h.add(q.curve.diameter), h.add(q.curve.percent_passing);
  h.add(q.porosity), h.add(q.diameter), h.add(q.length), h.add(q.seed);
  h.add(q.material.youngs_modulus), h.add(q.material.poisson_ratio), h.add(q.material.density);
  h.add(q.material_index), h.add(q.initial_solid_fraction), h.add(q.growth_stages);
  h.add(q.steps_per_stage), h.add(q.velocity_quench), h.add(q.damping_ratio);
  h.add(q.overlap_tolerance), h.add(q.max_settle_stages), h.add(q.max_rsa_attempts);
  h.add(q.jam), h.add(q.jam_friction), h.add(q.jam_overlap), h.add(q.jam_steps_per_stage);
  h.add(q.jam_velocity_quench);
  if (q.jam && q.jam_mass_scaling) h.add(q.jam_mass_scaling);  // earlier keys unchanged otherwise
  if (q.servo_walls) h.add(q.servo_walls), h.add(q.jam_mass_scaling);  // likewise
  if (q.packing_lock_rotation) h.add(q.packing_lock_rotation);
  if (q.initial_stress > 0) {  // unstressed packings keep the keys they had before
    h.add(q.initial_stress), h.add(q.prestress_friction), h.add(q.prestress_restitution);
    h.add(q.prestress_tolerance), h.add(q.prestress_servo_interval);
    h.add(q.prestress_max_steps), h.add(q.prestress_lock_rotation);
    h.add(q.prestress_wall_normal_stiffness), h.add(q.prestress_wall_shear_stiffness);
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h.h));
  return buf;
}

CachedPacking cached_packing(const PackingParams& params, const std::string& dir) {
  CachedPacking out;
  if (dir.empty()) {
    out.result = generate_packing(params);
    return out;
  }
  const std::string key = packing_cache_key(params);
  out.file = (fs::path(dir) / ("packing_" + key + ".bin")).string();
  const std::uint64_t k = std::stoull(key, nullptr, 16);
  PackingResult r;
  if (read_file(out.file, k, r)) {
    r.target_porosity = params.porosity;
    out.result = std::move(r);
    out.from_cache = true;
    return out;
  }
  if (params.initial_stress > 0) {
    // The unstressed packing (the expensive part) through the cache too, so packings
    // pre-stressed to different stresses share it.
    PackingParams base = params;
    base.initial_stress = 0;
    out.result = cached_packing(base, dir).result;
    prestress_result(out.result, params);
  } else {
    out.result = generate_packing(params);
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!ec) write_file(out.file, k, out.result);
  return out;
}

}  // namespace kolsky::dem
