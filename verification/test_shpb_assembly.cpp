// SHPB assemblies (shpb/assembly.hpp): the alternative is chosen once from the scene, builds
// only what it steps, and declares its probes as named records. Checked on every alternative
// the scenes can ask for (characteristic and sphere-chain bars with a column, characteristic
// bars with an fe and a dem specimen, meshed bars with an fe specimen):
//  - probe names are unique, units are SI strings, every probe has a description;
//  - all assemblies declare the common probes with the same names, units and order (the HDF5
//    order), gauges after them, model probes (DEM) last;
//  - run() records exactly the declared probes, each on the run's clock;
//  - meshed bars build no 1-D bar and no specimen object (the accessors say so), and refuse
//    a non-fe specimen before building it;
//  - a probe the assembly does not declare, asked for by name, fails naming it and the probes
//    the run has.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"

namespace kolsky {
namespace {

using nlohmann::json;

// Short bars and short runs: these tests look at structure, not at physics.
json scene(const std::string& bars_kind, const json& specimen, double end = 60e-6) {
  json bars = {{"kind", bars_kind},
               {"incident", {{"length", 0.3}, {"gauges", {0.15, 0.1}}}},
               {"transmission", {{"length", 0.2}, {"gauges", {0.1}}}}};
  if (bars_kind == "meshed") bars["mesh_radial"] = 2, bars["element_length"] = 0.01;
  return {{"bars", bars},
          {"pulse", {{"kind", "trapezoid"}, {"amplitude", 20e6}, {"rise_time", 10e-6},
                     {"duration", 40e-6}, {"fall_time", 10e-6}}},
          {"specimen", specimen},
          {"time", {{"end", end}}},
          {"output", {{"interval", 2e-6}}}};
}

const json kColumn = {{"model", "elastic"}, {"constrained_modulus", 230e6}};
const json kFe = {{"model", "fe"}, {"length", 0.0093}, {"diameter", 0.0191}, {"n_radial", 2},
                  {"n_axial", 2}, {"loading_curve", "data/digitized/chapter2/dry_eos_initial_guess.csv"},
                  {"unloading_modulus", 1e9}};
const json kDem = {{"model", "dem"},
                   {"grain_size_curve", "data/digitized/chapter4/song2009_psd_reconstructed.csv"},
                   {"upscale", 5.0}, {"seed", 7}, {"length", 0.006}, {"diameter", 0.008}};

shpb::ExperimentSpec spec_of(const json& j) {
  return scene::parse_scene(j, "test_shpb_assembly", KOLSKY_SOURCE_DIR).spec;
}

struct Case {
  std::string label;
  json scene;
  bool meshed, dem;
};

std::vector<Case> cases() {
  return {{"characteristic + column", scene("characteristic", kColumn), false, false},
          {"sphere chain + column", scene("sphere_chain", kColumn), false, false},
          {"characteristic + fe", scene("characteristic", kFe), false, false},
          {"characteristic + dem", scene("characteristic", kDem), false, true},
          {"meshed + fe", scene("meshed", kFe), true, false}};
}

const std::vector<std::string> kCommon = {
    "wave_incident", "wave_reflected", "wave_transmitted", "stress_front", "stress_back",
    "specimen_strain", "face_rate_front", "face_rate_back", "w_incident", "w_reflected",
    "w_transmitted", "energy_held", "energy_delivered", "applied_stress"};
const std::vector<std::string> kGauges = {"incident_gauge_strain", "incident_gauge_strain_2",
                                          "transmission_gauge_strain"};
const std::vector<std::string> kDemProbes = {"grain_kinetic_energy", "coordination_number",
                                             "coordination_with_walls", "grain_contacts",
                                             "wall_contacts"};

std::vector<std::string> names(const std::vector<shpb::Probe>& probes) {
  std::vector<std::string> n;
  for (const auto& p : probes) n.push_back(p.name);
  return n;
}

TEST(ShpbAssembly, ProbeRecordsHaveUniqueNamesSiUnitsAndDescriptions) {
  const std::set<std::string> units = {"Pa", "J", "m/s", "1"};
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const shpb::SimulatedShpb sim(spec_of(c.scene));
    const auto probes = sim.declared_probes();
    std::set<std::string> seen;
    for (const auto& p : probes) {
      EXPECT_TRUE(seen.insert(p.name).second) << "duplicate probe '" << p.name << "'";
      EXPECT_FALSE(p.name.empty());
      EXPECT_EQ(p.name.find('/'), std::string::npos) << p.name << ": an HDF5 group name";
      EXPECT_TRUE(units.count(p.unit)) << p.name << ": unit '" << p.unit << "'";
      EXPECT_FALSE(p.description.empty()) << p.name;
    }
  }
}

TEST(ShpbAssembly, EveryAssemblyDeclaresTheCommonProbesInOneOrder) {
  std::vector<shpb::Probe> reference;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.label);
    const shpb::SimulatedShpb sim(spec_of(c.scene));
    const auto probes = sim.declared_probes();
    std::vector<std::string> want = kCommon;
    want.insert(want.end(), kGauges.begin(), kGauges.end());
    if (c.dem) want.insert(want.end(), kDemProbes.begin(), kDemProbes.end());
    EXPECT_EQ(names(probes), want);
    if (reference.empty()) reference = probes;
    // Same unit for the same name, whichever bars ran: outputs and analysis do not care.
    for (std::size_t k = 0; k < std::min(probes.size(), reference.size()); ++k) {
      if (probes[k].name != reference[k].name) continue;
      EXPECT_EQ(probes[k].unit, reference[k].unit) << probes[k].name;
    }
  }
}

TEST(ShpbAssembly, RunRecordsExactlyTheDeclaredProbes) {
  for (const Case& c : cases()) {
    if (c.dem) continue;  // DEM runs: test_io_restart and test_io_snapshots
    SCOPED_TRACE(c.label);
    shpb::SimulatedShpb sim(spec_of(c.scene));
    const shpb::RunResult r = sim.run();
    ASSERT_TRUE(r.complete) << r.failure;
    EXPECT_EQ(names(r.probes), names(sim.declared_probes()));
    ASSERT_GT(r.t.size(), 10u);
    for (const auto& p : r.probes) EXPECT_EQ(p.value.size(), r.t.size()) << p.name;
    // The applied stress is the pulse itself, whatever the bars: a sampler that read the
    // wrong value would show here.
    const auto& applied = r.probe("applied_stress").value;
    EXPECT_DOUBLE_EQ(*std::max_element(applied.begin(), applied.end()), 20e6);
  }
}

TEST(ShpbAssembly, MeshedBarsBuildNoOneDimensionalBarsOrSpecimen) {
  const shpb::SimulatedShpb meshed(spec_of(scene("meshed", kFe)));
  EXPECT_TRUE(std::holds_alternative<shpb::MeshedBarsAssembly>(meshed.assembly()));
  EXPECT_THROW(meshed.specimen(), std::logic_error);
  EXPECT_THROW(meshed.incident_bar(), std::logic_error);
  EXPECT_THROW(meshed.transmission_bar(), std::logic_error);
  EXPECT_FALSE(meshed.can_checkpoint());
  EXPECT_GT(std::get<shpb::MeshedBarsAssembly>(meshed.assembly()).body().body().nodes().r0.size(), 0u);

  const shpb::SimulatedShpb one_dim(spec_of(scene("characteristic", kFe)));
  EXPECT_TRUE(std::holds_alternative<shpb::OneDimBarsAssembly>(one_dim.assembly()));
  EXPECT_TRUE(std::holds_alternative<fe::FeSpecimen>(one_dim.specimen()));
  EXPECT_TRUE(std::holds_alternative<bar::CharacteristicBar>(one_dim.incident_bar()));
}

TEST(ShpbAssembly, MeshedBarsRefuseAColumnSpecimenAndCoupleADemOne) {
  // Meshed bars take an fe specimen, or a dem one through the FE-DEM coupling (issue 16,
  // docs/coupling.md); a 1-D column specimen is refused with the bars' own error.
  shpb::ExperimentSpec spec = spec_of(scene("meshed", kFe));
  spec.specimen = spec_of(scene("characteristic", kColumn)).specimen;
  try {
    shpb::SimulatedShpb sim(spec);
    ADD_FAILURE() << "meshed bars accepted a column specimen";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "bars.kind");
  }
  // An unbuildable dem specimen (no grain-size curve) now reaches the coupled assembly, which
  // packs it: the packing's own error, not the bars'.
  spec.specimen = dem::DemSpecimenParams{};
  try {
    shpb::SimulatedShpb sim(spec);
    ADD_FAILURE() << "an empty grain-size curve was packed";
  } catch (const InputError& e) {
    ADD_FAILURE() << "refused as " << e.path() << ": " << e.what();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("grain-size curve"), std::string::npos) << e.what();
  }
}

TEST(ShpbAssembly, AProbeTheAssemblyDoesNotDeclareFailsByName) {
  shpb::SimulatedShpb sim(spec_of(scene("characteristic", kColumn, 20e-6)));
  const shpb::RunResult r = sim.run();
  EXPECT_FALSE(r.has_probe("grain_contacts"));
  try {
    r.probe("grain_contacts");
    ADD_FAILURE() << "a column run answered a DEM probe";
  } catch (const std::out_of_range& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'grain_contacts'"), std::string::npos) << what;
    EXPECT_NE(what.find("wave_incident"), std::string::npos) << what << ": should list what the run has";
  }
  // A bar without gauges declares no gauge probe: asked for, it fails the same way.
  // (Scenes always give each bar one; a library user need not.)
  shpb::ExperimentSpec no_gauges = spec_of(scene("characteristic", kColumn, 20e-6));
  no_gauges.transmission.gauges.clear();
  shpb::SimulatedShpb bare(no_gauges);
  const auto declared = names(bare.declared_probes());
  EXPECT_EQ(std::count(declared.begin(), declared.end(), "transmission_gauge_strain"), 0);
  EXPECT_THROW(bare.run().probe("transmission_gauge_strain"), std::out_of_range);
}

}  // namespace
}  // namespace kolsky
