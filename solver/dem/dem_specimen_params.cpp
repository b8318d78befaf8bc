// make_dem_specimen and the renaming of its input errors (see dem_specimen_params.hpp).
#include "dem/dem_specimen_params.hpp"

#include "core/errors.hpp"

namespace kolsky::dem {

namespace {
// `path` is `prefix` or lies under it: the prefix ends at a segment boundary.
bool under(const std::string& path, const std::string& prefix) {
  if (path.compare(0, prefix.size(), prefix) != 0) return false;
  return path.size() == prefix.size() || path[prefix.size()] == '.' || path[prefix.size()] == '[';
}
}  // namespace

InputError rename_input_error(const InputError& e, const std::vector<InputName>& names) {
  const InputName* best = nullptr;
  for (const InputName& n : names)
    if (under(e.path(), n.internal) && (!best || n.internal.size() > best->internal.size()))
      best = &n;
  if (!best) return e;
  return InputError(e.file(), best->external, e.rule());
}

DemSpecimen make_dem_specimen(const DemSpecimenParams& p) {
  try {
    if (p.rest) {  // before minutes of packing
      validate(*p.rest);
      // The relaxed grains press on the tube where it stands; a compliant tube's displacement
      // is not handed to the run, which would start out of equilibrium.
      if (p.walls.tube_compliance)
        throw InputError("", "dem.rest", "needs a rigid tube: a compliant tube's displacement is not "
                                         "carried from the relaxation into the run");
    }
    PackingResult packed = cached_packing(p.packing, p.packing_store).result;
    SpecimenWalls walls = p.walls;
    walls.length = p.packing.length;
    walls.radius = 0.5 * p.packing.diameter;
    std::vector<Material> materials{p.packing.material};
    DemOptions options = p.options;
    if (p.breakage) {
      // The criteria read the Hertz overlap, r' and E' (breakage_criterion.hpp).
      if (!std::holds_alternative<HertzMindlinParams>(p.contact))
        throw InputError("", "specimen.breakage", "needs specimen.contact_law = hertz_mindlin (the "
                                                  "breakage criteria read the Hertz overlap)");
      validate(*p.breakage);
      // A step fixed up front must already suit the smallest daughter the comminution limit
      // allows; a re-planned one follows the grains present.
      if (p.step_for_daughters_up_front)
        options.smallest_radius_to_come = smallest_radius_to_come(*p.breakage, packed.particles);
    }
    const std::uint64_t seed = p.packing.seed;
    ContactHistory history;
    std::optional<RestRelaxationOutcome> rest;
    if (p.rest) {
      // The grains relax in a specimen like the run's (same laws, walls and rolling), held by
      // nothing, with its step on the grains present (no daughters yet); the run then starts
      // from their positions with their contact histories.
      DemOptions prep_options = p.options;
      prep_options.smallest_radius_to_come = 0.0;
      SpecimenWalls prep_walls = walls;
      prep_walls.hold_until_loaded = false;
      DemSpecimen prep(std::move(packed.particles), materials,
                       make_contact_law(materials, p.contact), prep_walls, prep_options);
      // Progress through the packing's observer, as the preparation's last phase.
      std::function<void(const RestRelaxationOutcome&)> on_window;
      if (p.packing.on_progress)
        on_window = [&, most = p.rest->max_steps / p.rest->check_steps](const RestRelaxationOutcome& o) {
          PackingProgress q;
          q.phase = "relax";
          q.done = o.steps / p.rest->check_steps;
          q.most = most;
          q.value = o.kinetic_to_elastic;
          q.coordination = o.coordination_after;
          q.kinetic_to_elastic = o.kinetic_to_elastic;
          p.packing.on_progress(q);
        };
      rest = relax_to_rest(prep.coupled_system(), *p.rest, on_window);
      packed.particles = prep.system().particles();
      history = prep.system().contact_history();
    }
    DemSpecimen specimen(std::move(packed.particles), materials, make_contact_law(materials, p.contact), walls,
                         options, history);
    if (rest) specimen.set_rest_relaxation(*rest);
    if (p.breakage)
      specimen.enable_breakage(*p.breakage, seed);
    return specimen;
  } catch (const InputError& e) {
    throw rename_input_error(e, p.input_names);
  }
}

}  // namespace kolsky::dem
