// Checkpoint files (layout in checkpoint_hdf5.hpp). Each state struct is described once by a
// list of (name, member) pairs, generic in constness, so writer and reader cannot drift apart.
#include "io/checkpoint_hdf5.hpp"

#include <array>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"
#include "io/h5_util.hpp"

namespace kolsky::io {

namespace {

using h5::Handle;
constexpr std::int64_t kFormatVersion = 2;  // 2: the loop's schedule (refined dt), time_since_check
static_assert(sizeof(dem::Vec3) == 3 * sizeof(double), "Vec3 arrays are written as n x 3 doubles");

// ---- field lists: S is the state type, const or not ----

template <class S> auto char_scalars(S& s) {
  return std::array{std::pair{"intrusion", &s.intrusion}, std::pair{"rate_half", &s.rate_half},
                    std::pair{"rate_step", &s.rate_step}, std::pair{"s_in_step", &s.s_in_step},
                    std::pair{"dt", &s.dt}, std::pair{"delivered", &s.delivered},
                    std::pair{"power_prev", &s.power_prev}};
}
template <class S> auto char_arrays(S& s) { return std::array{std::pair{"s_out", &s.s_out}}; }
template <class S> auto chain_scalars(S& s) {
  return std::array{std::pair{"face_rate_step", &s.face_rate_step},
                    std::pair{"applied_work", &s.applied_work},
                    std::pair{"power_prev", &s.power_prev}};
}
template <class S> auto chain_arrays(S& s) {
  return std::array{std::pair{"d", &s.d}, std::pair{"v", &s.v}, std::pair{"v_prev", &s.v_prev},
                    std::pair{"f_contact", &s.f_contact}};
}
template <class S> auto column_arrays(S& s) {
  return std::array{std::pair{"u", &s.u}, std::pair{"v", &s.v}, std::pair{"strain", &s.strain},
                    std::pair{"stress", &s.stress}, std::pair{"max_strain", &s.max_strain},
                    std::pair{"work", &s.work}};
}
template <class S> auto dem_vec3s(S& s) {
  return std::array{std::pair{"x", &s.particles.x}, std::pair{"v", &s.particles.v},
                    std::pair{"omega", &s.particles.omega}, std::pair{"f", &s.particles.f},
                    std::pair{"torque", &s.particles.torque},
                    std::pair{"pair_history", &s.pair_history},
                    std::pair{"wall_history", &s.wall_history}};
}
template <class S> auto dem_arrays(S& s) {
  return std::array{std::pair{"radius", &s.particles.radius}, std::pair{"mass", &s.particles.mass},
                    std::pair{"inertia", &s.particles.inertia},
                    std::pair{"dissipated", &s.dissipated}};
}
template <class S> auto dem_ints(S& s) {
  return std::array{std::pair{"material", &s.particles.material}, std::pair{"pair_i", &s.pair_i},
                    std::pair{"pair_j", &s.pair_j}, std::pair{"wall_slot", &s.wall_slot},
                    std::pair{"wall_particle", &s.wall_particle}};
}
template <class S> auto loop_scalars(S& s) {
  return std::array{std::pair{"dt", &s.partial.dt}, std::pair{"stable_dt", &s.partial.stable_dt},
                    std::pair{"arrival_time", &s.partial.arrival_time}, std::pair{"w_i", &s.w_i},
                    std::pair{"w_r", &s.w_r}, std::pair{"w_t", &s.w_t},
                    std::pair{"injected", &s.injected}, std::pair{"force_front", &s.forces.front},
                    std::pair{"force_back", &s.forces.back},
                    // the schedule (time_loop::Schedule: as planned, or refined after breaks; format 2)
                    std::pair{"schedule_dt", &s.schedule.dt}, std::pair{"schedule_stable_dt", &s.schedule.stable_dt},
                    std::pair{"schedule_planned_dt", &s.schedule.planned_dt},
                    std::pair{"schedule_t_base", &s.schedule.t_base}};
}
template <class S> auto loop_counts(S& s) {
  return std::array{std::pair{"next_step", &s.next_step}, std::pair{"steps", &s.partial.steps},
                    std::pair{"schedule_n_steps", &s.schedule.n_steps},
                    std::pair{"schedule_sample_every", &s.schedule.sample_every},
                    std::pair{"schedule_n_base", &s.schedule.n_base},
                    std::pair{"schedule_tick_base", &s.schedule.tick_base},
                    std::pair{"schedule_ticks_per_planned_step", &s.schedule.ticks_per_planned_step},
                    std::pair{"schedule_refinements", &s.schedule.refinements}};
}

// ---- writing ----

template <class List> void put_scalars(hid_t g, const List& list) {
  for (const auto& [name, p] : list) h5::write_attr(g, name, *p);
}
template <class List> void put_counts(hid_t g, const List& list) {
  for (const auto& [name, p] : list) h5::write_attr(g, name, static_cast<std::int64_t>(*p));
}
template <class List> void put_arrays(hid_t g, const List& list) {
  for (const auto& [name, p] : list) h5::write_doubles(g, name, *p);
}
void put_vec3(hid_t g, const char* name, const std::vector<dem::Vec3>& v) {
  h5::write_doubles(g, name, v.empty() ? nullptr : &v[0].x, v.size(), 3);
}
void put_ints(hid_t g, const char* name, const std::vector<int>& v) {
  h5::write_ints(g, name, std::vector<std::int64_t>(v.begin(), v.end()));
}

// Breakage state in its own group "breakage" of the specimen (absent: no breakage).
void put_breakage(hid_t parent, const dem::DemBreakageState& b) {
  Handle g = h5::create_group(parent, "breakage");
  h5::write_ints(g.get(), "id", std::vector<std::int64_t>(b.id.begin(), b.id.end()));  // bits kept
  h5::write_doubles(g.get(), "strength", b.strength);
  put_ints(g.get(), "generation", b.generation);
  h5::write_attr(g.get(), "n_primary", static_cast<std::int64_t>(b.n_primary));
  h5::write_attr(g.get(), "n_secondary", static_cast<std::int64_t>(b.n_secondary));
  h5::write_attr(g.get(), "lost_volume", b.lost_volume);
  for (const auto& [name, v] : {std::pair{"fines_volume", &b.fines_volume}, std::pair{"fines_d_min", &b.fines_d_min},
                                std::pair{"fines_d_max", &b.fines_d_max}, std::pair{"fines_alpha", &b.fines_alpha}})
    h5::write_doubles(g.get(), name, *v);
  h5::write_attr(g.get(), "kinetic_removed", b.kinetic_removed);
  h5::write_attr(g.get(), "insertion_energy", b.insertion_energy);
  h5::write_attr(g.get(), "steps_since_check", static_cast<std::int64_t>(b.steps_since_check));
  h5::write_attr(g.get(), "time_since_check", b.time_since_check);  // format 2
}

dem::DemBreakageState get_breakage(hid_t parent) {
  Handle g = h5::open_group(parent, "breakage");
  dem::DemBreakageState b;
  for (std::int64_t v : h5::read_ints(g.get(), "id")) b.id.push_back(static_cast<std::uint64_t>(v));
  b.strength = h5::read_doubles(g.get(), "strength");
  for (std::int64_t v : h5::read_ints(g.get(), "generation")) b.generation.push_back(static_cast<int>(v));
  b.n_primary = static_cast<std::uint64_t>(h5::read_attr_int(g.get(), "n_primary"));
  b.n_secondary = static_cast<std::uint64_t>(h5::read_attr_int(g.get(), "n_secondary"));
  b.lost_volume = h5::read_attr_double(g.get(), "lost_volume");
  b.fines_volume = h5::read_doubles(g.get(), "fines_volume");
  b.fines_d_min = h5::read_doubles(g.get(), "fines_d_min");
  b.fines_d_max = h5::read_doubles(g.get(), "fines_d_max");
  b.fines_alpha = h5::read_doubles(g.get(), "fines_alpha");
  const std::size_t n = b.fines_volume.size();
  if (b.fines_d_min.size() != n || b.fines_d_max.size() != n || b.fines_alpha.size() != n)
    throw std::runtime_error("specimen/breakage: fines arrays of different lengths");
  b.kinetic_removed = h5::read_attr_double(g.get(), "kinetic_removed");
  b.insertion_energy = h5::read_attr_double(g.get(), "insertion_energy");
  b.steps_since_check = static_cast<long>(h5::read_attr_int(g.get(), "steps_since_check"));
  b.time_since_check = h5::read_attr_double(g.get(), "time_since_check");
  return b;
}

void put_dem(hid_t g, const dem::DemSpecimenState& s) {
  const dem::DemState& d = s.system;
  for (const auto& [name, p] : dem_vec3s(d)) put_vec3(g, name, *p);
  put_arrays(g, dem_arrays(d));
  for (const auto& [name, p] : dem_ints(d)) put_ints(g, name, *p);
  std::vector<double> planes, tubes;
  for (const auto& p : d.planes)
    planes.insert(planes.end(), {p.offset, p.speed, p.force, p.offset_at_force, p.work});
  for (const auto& t : d.tubes) tubes.insert(tubes.end(), {t.u, t.u_dot, t.force});
  h5::write_doubles(g, "planes", planes.data(), d.planes.size(), 5);
  h5::write_doubles(g, "tubes", tubes.data(), d.tubes.size(), 3);
  h5::write_attr(g, "time", d.time);
  h5::write_attr(g, "pending_dt", d.pending_dt);
  h5::write_attr(g, "forces_valid", std::int64_t{d.forces_valid});
  h5::write_attr(g, "n_rebuilds", static_cast<std::int64_t>(d.n_rebuilds));
  put_ints(g, "owner_blocks", d.owner_blocks);
  h5::write_attr(g, "removed_dissipated", d.removed_dissipated);
  h5::write_attr(g, "edited_energy", d.edited_energy);
  h5::write_attr(g, "added_since_sort", static_cast<std::int64_t>(d.added_since_sort));
  const FaceState& f = s.faces;
  h5::write_doubles(g, "faces", std::vector<double>{f.intrusion_front, f.intrusion_back,
                                                    f.rate_front, f.rate_back});
  h5::write_attr(g, "stepping", std::int64_t{s.stepping});
  h5::write_attr(g, "elastic_0", s.elastic_0);
  h5::write_attr(g, "held", std::int64_t{s.held});
  h5::write_attr(g, "held_work", s.held_work);
  if (s.breakage) put_breakage(g, *s.breakage);
}

void put_bar(hid_t parent, const char* name, const shpb::BarState& b) {
  Handle g = h5::create_group(parent, name);
  if (const auto* c = std::get_if<bar::CharacteristicBar::State>(&b)) {
    h5::write_attr(g.get(), "kind", std::string("characteristic"));
    put_scalars(g.get(), char_scalars(*c));
    put_arrays(g.get(), char_arrays(*c));
  } else {
    const auto& s = std::get<bar::SphereChainBar::State>(b);
    h5::write_attr(g.get(), "kind", std::string("sphere_chain"));
    put_scalars(g.get(), chain_scalars(s));
    put_arrays(g.get(), chain_arrays(s));
    h5::write_attr(g.get(), "first_step", std::int64_t{s.first_step});
  }
}

void write_all(hid_t file, const Checkpoint& c) {
  const shpb::ShpbState& s = c.state;
  h5::write_attr(file, "format", std::string("kolsky-checkpoint"));
  h5::write_attr(file, "format_version", kFormatVersion);
  h5::write_attr(file, "meta_json", c.meta.dump());
  Handle loop = h5::create_group(file, "loop");
  put_counts(loop.get(), loop_counts(s));
  put_scalars(loop.get(), loop_scalars(s));
  h5::write_doubles(loop.get(), "prev", s.prev, 3);
  h5::write_doubles(loop.get(), "t", s.partial.t);
  Handle probes = h5::create_group(file, "probes");
  h5::write_attr(probes.get(), "count", static_cast<std::int64_t>(s.partial.probes.size()));
  for (std::size_t k = 0; k < s.partial.probes.size(); ++k) {
    const shpb::Probe& p = s.partial.probes[k];
    Handle g = h5::create_group(probes.get(), std::to_string(k));
    h5::write_attr(g.get(), "name", p.name);
    h5::write_attr(g.get(), "unit", p.unit);
    h5::write_attr(g.get(), "description", p.description);
    h5::write_doubles(g.get(), "value", p.value);
  }
  Handle bars = h5::create_group(file, "bars");
  put_bar(bars.get(), "incident", s.incident);
  put_bar(bars.get(), "transmission", s.transmission);
  Handle spec = h5::create_group(file, "specimen");
  if (const auto* col = std::get_if<bar::SpecimenColumn::State>(&s.specimen)) {
    h5::write_attr(spec.get(), "kind", std::string("column"));
    put_arrays(spec.get(), column_arrays(*col));
    h5::write_attr(spec.get(), "kinetic_interior", col->kinetic_interior);
  } else {
    h5::write_attr(spec.get(), "kind", std::string("dem"));
    put_dem(spec.get(), std::get<dem::DemSpecimenState>(s.specimen));
  }
}

// ---- reading ----

template <class List> void get_scalars(hid_t g, const List& list) {
  for (const auto& [name, p] : list) *p = h5::read_attr_double(g, name);
}
template <class List> void get_counts(hid_t g, const List& list) {
  for (const auto& [name, p] : list) *p = static_cast<long>(h5::read_attr_int(g, name));
}
template <class List> void get_arrays(hid_t g, const List& list) {
  for (const auto& [name, p] : list) *p = h5::read_doubles(g, name);
}
std::vector<dem::Vec3> get_vec3(hid_t g, const char* name) {
  const std::vector<double> flat = h5::read_doubles(g, name, 3);
  std::vector<dem::Vec3> v(flat.size() / 3);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
  return v;
}
std::vector<int> get_ints(hid_t g, const char* name) {
  const std::vector<std::int64_t> v = h5::read_ints(g, name);
  return std::vector<int>(v.begin(), v.end());
}

dem::DemSpecimenState get_dem(hid_t g) {
  dem::DemSpecimenState s;
  dem::DemState& d = s.system;
  for (const auto& [name, p] : dem_vec3s(d)) *p = get_vec3(g, name);
  get_arrays(g, dem_arrays(d));
  for (const auto& [name, p] : dem_ints(d)) *p = get_ints(g, name);
  const std::vector<double> planes = h5::read_doubles(g, "planes", 5);
  for (std::size_t k = 0; k + 4 < planes.size(); k += 5)
    d.planes.push_back({planes[k], planes[k + 1], planes[k + 2], planes[k + 3], planes[k + 4]});
  const std::vector<double> tubes = h5::read_doubles(g, "tubes", 3);
  for (std::size_t k = 0; k + 2 < tubes.size(); k += 3)
    d.tubes.push_back({tubes[k], tubes[k + 1], tubes[k + 2]});
  d.time = h5::read_attr_double(g, "time");
  d.pending_dt = h5::read_attr_double(g, "pending_dt");
  d.forces_valid = h5::read_attr_int(g, "forces_valid") != 0;
  d.n_rebuilds = static_cast<std::size_t>(h5::read_attr_int(g, "n_rebuilds"));
  // Absent in checkpoints written before particle edits: uniform blocks, nothing edited.
  if (h5::exists(g, "owner_blocks")) d.owner_blocks = get_ints(g, "owner_blocks");
  if (H5Aexists(g, "removed_dissipated") > 0) d.removed_dissipated = h5::read_attr_double(g, "removed_dissipated");
  if (H5Aexists(g, "edited_energy") > 0) d.edited_energy = h5::read_attr_double(g, "edited_energy");
  if (H5Aexists(g, "added_since_sort") > 0)
    d.added_since_sort = static_cast<std::size_t>(h5::read_attr_int(g, "added_since_sort"));
  const std::vector<double> f = h5::read_doubles(g, "faces");
  if (f.size() != 4) throw std::runtime_error("specimen/faces must hold 4 values");
  s.faces = {f[0], f[1], f[2], f[3]};
  s.stepping = h5::read_attr_int(g, "stepping") != 0;
  s.elastic_0 = h5::read_attr_double(g, "elastic_0");
  s.held = H5Aexists(g, "held") > 0 && h5::read_attr_int(g, "held") != 0;  // absent: older file
  s.held_work = H5Aexists(g, "held_work") > 0 ? h5::read_attr_double(g, "held_work") : 0.0;
  if (h5::exists(g, "breakage")) s.breakage = get_breakage(g);
  return s;
}

shpb::BarState get_bar(hid_t parent, const char* name) {
  Handle g = h5::open_group(parent, name);
  const std::string kind = h5::read_attr_string(g.get(), "kind");
  if (kind == "characteristic") {
    bar::CharacteristicBar::State s;
    get_scalars(g.get(), char_scalars(s));
    get_arrays(g.get(), char_arrays(s));
    return s;
  }
  if (kind != "sphere_chain") throw std::runtime_error(std::string("unknown bar kind '") + kind + "'");
  bar::SphereChainBar::State s;
  get_scalars(g.get(), chain_scalars(s));
  get_arrays(g.get(), chain_arrays(s));
  s.first_step = h5::read_attr_int(g.get(), "first_step") != 0;
  return s;
}

Checkpoint read_all(hid_t file) {
  if (!H5Aexists(file, "format") || h5::read_attr_string(file, "format") != "kolsky-checkpoint")
    throw std::runtime_error("not a kolsky checkpoint file");
  const std::int64_t version = h5::read_attr_int(file, "format_version");
  if (version != kFormatVersion)
    throw std::runtime_error("checkpoint format version " + std::to_string(version) +
                             " (this kolsky reads " + std::to_string(kFormatVersion) + ")");
  Checkpoint c;
  c.meta = nlohmann::json::parse(h5::read_attr_string(file, "meta_json"));
  shpb::ShpbState& s = c.state;
  Handle loop = h5::open_group(file, "loop");
  get_counts(loop.get(), loop_counts(s));
  get_scalars(loop.get(), loop_scalars(s));
  const std::vector<double> prev = h5::read_doubles(loop.get(), "prev");
  if (prev.size() != 3) throw std::runtime_error("loop/prev must hold 3 values");
  std::copy(prev.begin(), prev.end(), s.prev);
  s.partial.t = h5::read_doubles(loop.get(), "t");
  Handle probes = h5::open_group(file, "probes");
  const std::int64_t count = h5::read_attr_int(probes.get(), "count");
  for (std::int64_t k = 0; k < count; ++k) {
    Handle g = h5::open_group(probes.get(), std::to_string(k));
    shpb::Probe p;
    p.name = h5::read_attr_string(g.get(), "name");
    p.unit = h5::read_attr_string(g.get(), "unit");
    p.description = h5::read_attr_string(g.get(), "description");
    p.value = h5::read_doubles(g.get(), "value");
    s.partial.probes.push_back(std::move(p));
  }
  Handle bars = h5::open_group(file, "bars");
  s.incident = get_bar(bars.get(), "incident");
  s.transmission = get_bar(bars.get(), "transmission");
  Handle spec = h5::open_group(file, "specimen");
  const std::string kind = h5::read_attr_string(spec.get(), "kind");
  if (kind == "column") {
    bar::SpecimenColumn::State col;
    get_arrays(spec.get(), column_arrays(col));
    col.kinetic_interior = h5::read_attr_double(spec.get(), "kinetic_interior");
    s.specimen = col;
  } else if (kind == "dem") {
    s.specimen = get_dem(spec.get());
  } else {
    throw std::runtime_error("unknown specimen kind '" + kind + "'");
  }
  return c;
}

}  // namespace

void write_checkpoint_hdf5(const std::string& path, const Checkpoint& c) {
  h5::write_file_atomic(path, "checkpoint", [&](hid_t file) { write_all(file, c); });
}

Checkpoint read_checkpoint_hdf5(const std::string& path) {
  h5::silence();
  try {
    Handle file = h5::open_file_read(path);
    return read_all(file.get());
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("cannot read checkpoint: ") + e.what());
  }
}

}  // namespace kolsky::io
