// Internal to scene/: the scene keys of the DEM specimen's contact laws and breakage, each with the struct
// field it fills (its default is that field's initialiser, so a default is written once, in
// solver/dem/), the field's name in the physics' error paths, unit, range and a one-line
// description with its source. The table rows (schema_dem.cpp), the parser (scene_dem.cpp)
// and the renaming of the physics' errors to scene keys (dem_input_names) all read these lists.
#pragma once
#include <string>
#include <variant>
#include <vector>

#include "dem/contact_law.hpp"
#include "dem/dem_specimen_params.hpp"
#include "scene/schema.hpp"

namespace kolsky::scene {

template <class P>
struct LawKey {
  std::string key;           ///< under "specimen."
  double P::*field;          ///< what the key fills
  std::string physics_name;  ///< the field in the physics' paths (dem.contact_law.<this>)
  std::string unit;
  Range range;
  std::string description;
};

/// The keys of each grain law (contact_law.hpp order), chosen by its parameter struct.
const std::vector<LawKey<dem::HertzMindlinParams>>& law_keys(const dem::HertzMindlinParams&);
const std::vector<LawKey<dem::LinearParams>>& law_keys(const dem::LinearParams&);
const std::vector<LawKey<dem::LsDynaParams>>& law_keys(const dem::LsDynaParams&);
/// The keys of the linear wall contact (ends and tube; Table 4.1).
const std::vector<LawKey<dem::LinearParams>>& wall_keys();

/// A specimen.breakage key: like LawKey, for a field of any scalar type; the key is the field's
/// name, which is also its name in the physics' errors (breakage_model.hpp's validate paths).
template <class P>
struct BreakageKey {
  std::string key;  ///< under "specimen.breakage."
  std::variant<double P::*, int P::*, bool P::*> field;
  std::string unit;
  Range range;
  std::string description;
};

/// The keys of each breakage criterion (breakage_criterion.hpp), chosen by its struct.
const std::vector<BreakageKey<dem::HertzianContactCriterion>>& breakage_keys(
    const dem::HertzianContactCriterion&);
const std::vector<BreakageKey<dem::ConstantStressCriterion>>& breakage_keys(
    const dem::ConstantStressCriterion&);
/// The keys every criterion shares: the limits and the fines (BreakageParams), the cadence.
const std::vector<BreakageKey<dem::BreakageParams>>& breakage_limit_keys();
const std::vector<BreakageKey<dem::BreakageCadence>>& breakage_cadence_keys();

/// The physics' names of the DEM specimen's inputs and their scene keys, for
/// DemSpecimenParams::input_names (dem_specimen_params.hpp): an error while the specimen is
/// built then names the key the user wrote (docs/scene.md, "Rules"). `law`: the selected grain
/// law, whose keys the law's field names stand for.
std::vector<dem::InputName> dem_input_names(const dem::ContactLawParams& law);

}  // namespace kolsky::scene
