// The one parameter table of scene files and BARS.json. Defaults are taken from the default
// member initializers of the structs the parsers fill (so table and structs cannot drift apart)
// except where a key is required or its default depends on another key. Ranges are the
// validation rules; the parsers apply them by looking the key up here. The DEM specimen's rows
// (packing, grains, contact laws, walls) are in schema_dem.cpp, the builder in schema_builder.hpp.
#include "scene/schema.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "bar/material.hpp"
#include "bar/pulse.hpp"
#include "bar/specimen_column.hpp"
#include "fe/fe_specimen.hpp"
#include "shpb/analysis.hpp"
#include "shpb/experiment.hpp"
#include "shpb/gauge_processing.hpp"
#include "scene/schema_builder.hpp"

namespace kolsky::scene {

namespace {

using namespace table;

void add_scene_bar(TableBuilder& t, const std::string& side) {
  const std::string p = "bars." + side + ".";
  const bar::BarMaterial m;
  const bar::BarGeometry g;
  t.add(VT::number, p + "length", kRequired, "m", kPositive, "Bar length");
  t.add(VT::number, p + "diameter", g.diameter, "m", kPositive,
        "Bar diameter (also the ball diameter of a sphere chain)");
  t.add(VT::number, p + "youngs_modulus", m.youngs_modulus, "Pa", kPositive, "Young's modulus E");
  t.add(VT::number, p + "density", m.density, "kg/m^3", kPositive, "Density rho");
  t.add(VT::number, p + "poisson_ratio", m.poisson_ratio, "-", kPoisson,
        "Poisson ratio (dispersion correction only)");
  t.add_derived(VT::number_list, p + "gauges", "[length/2]", "m", kPositive,
                "Gauge distances from the specimen face, each strictly inside (0, length); at most "
                "1000 per bar (each is a probe of the run file)");
  t.add(VT::integer, p + "n_spheres", shpb::BarSpec{}.n_spheres, "-", kSphereCount,
        "Ball count; 0 = round(length/diameter), Eq. 4.3", "bars.kind=sphere_chain");
}

void add_bars_file_bar(TableBuilder& t, const std::string& side) {
  const std::string p = side + ".";
  const shpb::AnalysisBar b;
  t.add(VT::number, p + "youngs_modulus", b.youngs_modulus, "Pa", kPositive, "Young's modulus E");
  t.add(VT::number, p + "density", b.density, "kg/m^3", kPositive, "Density rho");
  t.add(VT::number, p + "poisson_ratio", b.poisson_ratio, "-", kPoisson,
        "Poisson ratio (dispersion correction only)");
  t.add(VT::number, p + "diameter", b.diameter, "m", kPositive, "Bar diameter");
  t.add(VT::number, p + "gauge_distance", kRequired, "m", kPositive,
        "Distance from the strain gauge to the specimen face");
}

// The scene's title and bars.
void add_bar_rows(TableBuilder& s) {
  s.add(VT::string, "title", std::string(), "-", kNoRange,
        "Free-text title, copied into the outputs");
  s.add(VT::choice, "bars.kind", "characteristic", "-", kNoRange,
        "Bar model: characteristic (exact delay line), sphere_chain (Sec. 4.3) or meshed "
        "(axisymmetric FE bars, specimen.model = fe only)", "",
        {"characteristic", "sphere_chain", "meshed"});
  const shpb::BarMeshSpec bm;
  s.add(VT::integer, "bars.mesh_radial", bm.n_radial, "-", kMeshCount,
        "Radial elements of each meshed bar", "bars.kind=meshed");
  s.add(VT::number, "bars.element_length", bm.element_length, "m", kPositive,
        "Target axial element length of the meshed bars", "bars.kind=meshed");
  add_scene_bar(s, "incident");
  add_scene_bar(s, "transmission");
}

// The incident pulse at the free end.
void add_pulse_rows(TableBuilder& s) {
  const bar::TrapezoidPulse trap;
  const bar::TabulatedPulse tab;
  s.add(VT::choice, "pulse.kind", kRequired, "-", kNoRange,
        "Incident stress history at the free end: trapezoid, half_sine or tabulated", "",
        {"trapezoid", "half_sine", "tabulated"});
  s.add(VT::number, "pulse.amplitude", kRequired, "Pa", kPositive,
        "Peak stress, compression positive", "pulse.kind=trapezoid|half_sine");
  s.add(VT::number, "pulse.rise_time", trap.rise_time, "s", kNonNegative, "Linear rise time",
        "pulse.kind=trapezoid");
  s.add(VT::number, "pulse.fall_time", trap.fall_time, "s", kNonNegative,
        "Linear fall time; rise_time + fall_time <= duration", "pulse.kind=trapezoid");
  s.add(VT::number, "pulse.duration", kRequired, "s", kPositive, "Total pulse length",
        "pulse.kind=trapezoid|half_sine");
  s.add(VT::number, "pulse.delay", trap.delay, "s", kNonNegative,
        "Start time of the pulse at the free end");
  s.add(VT::path, "pulse.file", kRequired, "path", kNoRange,
        "CSV table time_s,stress_pa, time strictly increasing", "pulse.kind=tabulated");
  s.add(VT::number, "pulse.scale", tab.scale, "-", kPositive,
        "Factor applied to the tabulated stress", "pulse.kind=tabulated");
}

// What loads the specimen.
void add_loading_rows(TableBuilder& s) {
  // Sec. 5.2.1: methodology 2 (bars) for tests that report the incident wave, methodology 1
  // (strain_rate) for those that report only the strain rate (Wang 2018, Huang 2013).
  s.add(VT::choice, "loading.kind", "bars", "-", kNoRange,
        "What loads the specimen: bars (the pulse through the bars) or strain_rate (Sec. 5.2.1, "
        "methodology 1: no bars, the incident-side wall moves to impose a tabulated strain rate, "
        "the transmission-side wall is fixed; specimen.model = dem only; no bars or pulse keys)",
        "", {"bars", "strain_rate"});
  s.add(VT::path, "loading.file", kRequired, "path", kNoRange,
        "CSV table time_s,strain_rate (1/s, compression +), time strictly increasing from >= 0; "
        "rate linear between rows, 0 after the last row; strain by Eq. 5.1",
        "loading.kind=strain_rate");
  s.add(VT::number, "loading.end_at_back_stress", shpb::ExperimentSpec{}.end_at_back_stress, "Pa",
        kNonNegative,
        "0: the run lasts time.end; > 0: it ends (complete) at the first probe sample whose "
        "back-wall stress reaches this, or at time.end if it never does (a test loaded until a "
        "stress: Sec. 5.3.1 compares the Wang specimens at 72 MPa)",
        "loading.kind=strain_rate");
}

// The specimen: the 1-D column and the axisymmetric FE model (the DEM rows: schema_dem.cpp).
void add_specimen_rows(TableBuilder& s) {
  const bar::ColumnParams col;
  s.add(VT::choice, "specimen.model", kRequired, "-", kNoRange,
        "Specimen model: 1-D column (elastic or compaction), axisymmetric FE (fe, Sec. 2.3) or "
        "DEM packing (dem, Sec. 4.3)",
        "", {"elastic", "compaction", "fe", "dem"});
  s.add(VT::number, "specimen.length", col.length, "m", kPositive, "Specimen length L_s");
  s.add(VT::number, "specimen.diameter", col.diameter, "m", kPositive,
        "Specimen diameter, at most 4 x the bar diameter");
  s.add(VT::number, "specimen.density", col.density, "kg/m^3", kPositive, "Specimen density",
        "specimen.model=elastic|compaction|fe");
  s.add(VT::integer, "specimen.n_elements", col.n_elements, "-", kElementCount,
        "Two-node elements along the specimen", "specimen.model=elastic|compaction");
  s.add(VT::number, "specimen.constrained_modulus", kRequired, "Pa", kPositive,
        "Constrained (uniaxial-strain) modulus D", "specimen.model=elastic");
  s.add(VT::path, "specimen.loading_curve", kRequired, "path", kNoRange,
        "CSV table strain,stress_pa from (0, 0), both columns strictly increasing (fe: "
        "volumetric strain -> pressure, the compaction EOS)",
        "specimen.model=compaction|fe");
  s.add(VT::number, "specimen.unloading_modulus", kRequired, "Pa", kPositive,
        "Slope of unloading/reloading from the largest strain reached (fe: bulk modulus)",
        "specimen.model=compaction|fe");
  const fe::FeSpecimenParams fep;
  const fe::PseudoTensorModeI pt;
  const fe::MeshedTube mt;
  s.add(VT::integer, "specimen.n_radial", fep.n_r, "-", kMeshCount,
        "Radial elements of the specimen mesh", "specimen.model=fe");
  s.add(VT::integer, "specimen.n_axial", fep.n_z, "-", kMeshCount,
        "Axial elements of the specimen mesh", "specimen.model=fe");
  s.add(VT::number, "specimen.shear_modulus", pt.shear_modulus, "Pa", kPositive,
        "Shear modulus G of the pseudo-tensor model (Sec. 2.3.2)", "specimen.model=fe");
  s.add(VT::number, "specimen.friction_angle", pt.friction_angle_deg, "deg", kFrictionAngle,
        "Mohr-Coulomb friction angle, Mode I (Sec. 2.3.2)", "specimen.model=fe");
  s.add(VT::number, "specimen.cohesion", pt.cohesion, "Pa", kNonNegative,
        "Mohr-Coulomb cohesion (Sec. 2.3.2: zero)", "specimen.model=fe");
  s.add(VT::choice, "specimen.tube", "rigid", "-", kNoRange,
        "Confining tube: none, rigid, spring (Lame wall) or meshed; a dem specimen's is rigid, "
        "spring (the grains' cylinder with the thick tube's Lame stiffness and its mass over the "
        "specimen length; not with bars.kind = meshed) or meshed (bars.kind = meshed: the FE-DEM "
        "coupling; characteristic: an FE tube around the grains), docs/coupling.md; spring and "
        "meshed read the tube_* keys",
        "specimen.model=fe|dem", {"none", "rigid", "spring", "meshed"});
  s.add(VT::number, "specimen.tube_youngs_modulus", mt.material.youngs_modulus, "Pa", kPositive,
        "Tube E (steel 200e9, polycarbonate 1.4e9; Sec. 2.3.1)", "specimen.model=fe");
  s.add(VT::number, "specimen.tube_poisson_ratio", mt.material.poisson_ratio, "-", kPoisson,
        "Tube Poisson ratio (steel 0.33, polycarbonate 0.3)", "specimen.model=fe");
  s.add(VT::number, "specimen.tube_density", mt.material.density, "kg/m^3", kPositive,
        "Tube density (steel 8100, polycarbonate 1500)", "specimen.model=fe");
  s.add(VT::number, "specimen.tube_thickness", mt.thickness, "m", kPositive,
        "Tube wall thickness (not given in the text: a choice)", "specimen.model=fe");
  s.add(VT::number, "specimen.tube_length", mt.length, "m", kPositive,
        "Meshed tube length, at least the specimen length", "specimen.model=fe");
  s.add(VT::number, "specimen.friction_faces", fep.friction_faces, "-", kNonNegative,
        "Coulomb friction at both bar faces (Sec. 2.4.2: 0 or 0.2)", "specimen.model=fe");
  s.add(VT::number, "specimen.friction_tube", fep.friction_tube, "-", kNonNegative,
        "Coulomb friction at the tube wall", "specimen.model=fe");
  s.add(VT::number, "specimen.penalty_scale", fep.penalty_scale, "-", kPositive,
        "Contact penalty stiffness factor (docs/fe.md)", "specimen.model=fe");
  s.add(VT::number, "specimen.contact_damping", fep.contact_damping, "-", kNonNegative,
        "Normal contact damping, fraction of critical (docs/fe.md)", "specimen.model=fe");
}

// Time stepping and outputs.
void add_time_output_rows(TableBuilder& s) {
  const shpb::TimeSpec time;
  s.add(VT::number, "time.end", kRequired, "s", kPositive,
        "Simulated time; at most 1e10 steps (time.end / dt, time_loop::kMaxSteps), and long "
        "enough for two probe samples after the incident wave reaches the specimen");
  s.add(VT::number, "time.dt", time.dt, "s", kNonNegative,
        "Time step; 0 = safety_factor x stable time step (see time.refine_after_breaks)");
  s.add_derived(VT::number, "time.safety_factor", "0.5; 0.15 for specimen.model = dem", "-",
                kHalfOpenUnitUpper,
                "Fraction of the models' raw stable time step used when dt = 0 (the run's only "
                "safety factor; a DEM specimen's raw limit is the single-contact Rayleigh step)");
  s.add(VT::boolean, "time.check_stability", time.check_stability, "-", kNoRange,
        "true: a time.dt above the stability limit is refused and a run stops on energy growth "
        "or a step above a model's limit (exit 3); false lifts all of these, only to test that "
        "an unstable step is stopped once its values overflow (non-finite values always stop a "
        "run; the DEM engine always refuses a step above its grains' limit)");
  s.add(VT::boolean, "time.refine_after_breaks", time.refine_after_breaks, "-", kNoRange,
        "With time.dt = 0 and loading.kind = strain_rate: true refines dt after a break lowers "
        "the stable step (faster; breakage statistics not converged at the Chapter 5 safety "
        "factor); false plans for the smallest possible daughter from the first step "
        "(docs/breakage.md 'Time step'; bar assemblies always plan up front)");
  s.add_derived(VT::number, "time.energy_tolerance", "0.01; 0.05 for loading.kind = strain_rate",
                "-", kPositive,
                "Relative energy growth that counts as a blow-up (strain-rate walls judge against "
                "their own work, shpb::kWallsEnergyTolerance)");
  s.add(VT::number, "output.interval", shpb::OutputSpec{}.interval, "s", kNonNegative,
        "Probe sampling interval; 0 = every 1e-6 s (rounded to whole steps)");
  s.add(VT::number, "output.snapshot_interval", shpb::OutputSpec{}.snapshot_interval, "s",
        kNonNegative,
        "Particle snapshot interval (position, radius, velocity, force in OUT.particles.h5, "
        "OUT.xmf for ParaView); 0 = none; rounded to whole steps",
        "specimen.model=dem");
}

// BARS.json of `kolsky analyze`: the bars, the specimen size and the gauge processing.
void add_bars_file_rows(TableBuilder& b) {
  add_bars_file_bar(b, "incident");
  add_bars_file_bar(b, "transmission");
  const shpb::AnalysisSetup setup;
  b.add(VT::number, "specimen.length", kRequired, "m", kPositive, "Specimen length L_s");
  b.add(VT::number, "specimen.diameter", setup.specimen_diameter, "m", kPositive,
        "Specimen diameter, at most 4 x the bar diameter");
  const shpb::GaugeOptions gauge;
  b.add(VT::number, "processing.threshold_fraction", gauge.threshold_fraction, "-", kOpenUnit,
        "Pulse-start threshold as a fraction of the incident peak");
  b.add(VT::number, "processing.noise_sigmas", gauge.noise_sigmas, "-", kNonNegative,
        "Detection threshold floor in units of the pre-trigger noise sigma");
  b.add(VT::number, "processing.pretrigger_fraction", gauge.pretrigger_fraction, "-", kOpenUnit,
        "Fallback pre-trigger window (fraction of the record) if the pulse starts early");
  b.add(VT::boolean, "processing.dispersion_correction", gauge.dispersion_correction, "-",
        kNoRange, "First Pochhammer-Chree mode correction instead of a pure time shift");
  b.add(VT::number, "processing.duration", gauge.duration, "s", kNonNegative,
        "Analysis window after the incident arrival; 0 = automatic");
  b.add(VT::number, "processing.alpha_floor_fraction", shpb::AnalysisOptions{}.alpha_floor_fraction,
        "-", kHalfOpenUnitLower,
        "alpha(t) is reported only where abs(stress_avg) >= this x its peak");
}

std::vector<ParamSpec> build_table() {
  std::vector<ParamSpec> rows;
  TableBuilder s(rows, "scene");
  add_bar_rows(s);
  add_pulse_rows(s);
  add_loading_rows(s);
  add_specimen_rows(s);
  add_dem_rows(s);
  add_time_output_rows(s);
  TableBuilder b(rows, "bars");
  add_bars_file_rows(b);
  return rows;
}

std::string bound(double v) { return format_number(v); }

}  // namespace

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (or_zero && v == 0.0) return true;
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::text() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  std::string s;
  if (has_lo && has_hi)
    s = (lo_open ? "(" : "[") + bound(lo) + ", " + bound(hi) + (hi_open ? ")" : "]");
  else if (has_lo)
    s = (lo_open ? "> " : ">= ") + bound(lo);
  else if (has_hi)
    s = (hi_open ? "< " : "<= ") + bound(hi);
  return s.empty() || !or_zero ? s : "0 or " + s;
}

std::string Range::describe() const {
  const std::string t = text();
  if (t.empty()) return "must be finite";
  const bool interval = std::isfinite(lo) && std::isfinite(hi);
  if (or_zero) return "must be 0 or " + std::string(interval ? "in " : "") + t.substr(5);
  return "must be " + std::string(interval ? "in " : "") + t;
}

const std::vector<ParamSpec>& schema_table() {
  static const std::vector<ParamSpec> table = build_table();
  return table;
}

const ParamSpec* find_param(std::string_view schema, std::string_view path) {
  for (const ParamSpec& p : schema_table())
    if (p.doc.schema == schema && p.doc.path == path) return &p;
  return nullptr;
}

std::string describe_applies_to(const std::string& applies_to) {
  const auto eq = applies_to.find('=');
  if (eq == std::string::npos) return applies_to;
  std::string values = applies_to.substr(eq + 1);
  for (size_t bar = values.find('|'); bar != std::string::npos; bar = values.find('|'))
    values.replace(bar, 1, " or ");
  return applies_to.substr(0, eq) + " = " + values;
}

std::string format_number(double v) {
  char buf[40];
  const double a = std::fabs(v);
  // Plain notation where it stays short; otherwise engineering notation (exponent a multiple
  // of 3) so that 200e9 Pa and 50e-6 s read as they are usually written.
  if (a == 0.0 || (a >= 1e-3 && a < 1e6)) {
    std::snprintf(buf, sizeof buf, "%.12g", v);
    return buf;
  }
  int e3 = static_cast<int>(std::floor(std::log10(a) / 3.0)) * 3;
  double m = v / std::pow(10.0, e3);
  if (std::fabs(m) >= 1000.0 - 1e-9) m /= 1000.0, e3 += 3;  // log10 rounding at 1e9, 1e-6, ...
  if (std::fabs(m) < 1.0 - 1e-12) m *= 1000.0, e3 -= 3;
  std::snprintf(buf, sizeof buf, "%.12ge%d", m, e3);
  return buf;
}

const std::vector<ParamDoc>& parameters() {
  static const std::vector<ParamDoc> docs = [] {
    std::vector<ParamDoc> d;
    for (const ParamSpec& p : schema_table()) d.push_back(p.doc);
    return d;
  }();
  return docs;
}

std::string format_defaults() {
  const std::pair<const char*, const char*> groups[] = {
      {"scene", "Scene file (kolsky run SCENE.json)"}, {"bars", "BARS.json (kolsky analyze)"}};
  std::string out;
  for (const auto& [schema, title] : groups) {
    std::vector<std::array<std::string, 6>> rows{
        {"key", "type", "default", "unit", "range", "description"}};
    for (const ParamSpec& p : schema_table()) {
      const ParamDoc& d = p.doc;
      if (d.schema != schema) continue;
      std::string desc = d.description;
      if (!d.applies_to.empty()) desc += " (" + describe_applies_to(d.applies_to) + ")";
      rows.push_back({d.path, d.type, d.default_value, d.unit, p.range.text(), desc});
    }
    std::array<size_t, 6> width{};
    for (const auto& r : rows)
      for (size_t c = 0; c < r.size(); ++c) width[c] = std::max(width[c], r[c].size());
    if (!out.empty()) out += "\n";
    out += std::string(title) + "\n";
    for (const auto& r : rows) {
      std::string line = " ";
      for (size_t c = 0; c < r.size(); ++c) {
        line += " " + r[c];
        if (c + 1 < r.size()) line += std::string(width[c] - r[c].size() + 1, ' ');
      }
      out += line + "\n";
    }
  }
  return out;
}

}  // namespace kolsky::scene
