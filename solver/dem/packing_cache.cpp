// Packing cache (see packing_cache.hpp).
#include "dem/packing_cache.hpp"

#include <cstdio>
#include <cstring>
#include <type_traits>
#include <vector>

#include "core/hash.hpp"

namespace kolsky::dem {

namespace {

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

CachedPacking cached_packing(const PackingParams& params, const PackingStore& store) {
  CachedPacking out;
  if (!store) {
    out.result = generate_packing(params);
    return out;
  }
  const std::string key = packing_cache_key(params);
  out.file = store.name ? store.name(key) : key;
  PackingResult r;
  if (store.load(key, r)) {
    r.target_porosity = params.porosity;
    out.result = std::move(r);
    out.from_cache = true;
    return out;
  }
  if (params.initial_stress > 0) {
    // The unstressed packing (the expensive part) through the store too, so packings
    // pre-stressed to different stresses share it.
    PackingParams base = params;
    base.initial_stress = 0;
    out.result = cached_packing(base, store).result;
    prestress_result(out.result, params);
  } else {
    out.result = generate_packing(params);
  }
  if (store.save) store.save(key, out.result);
  return out;
}

}  // namespace kolsky::dem
