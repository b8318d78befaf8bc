// The simulated SHPB test: incident bar, specimen, transmission bar, coupled through the face
// degrees of freedom, advanced by the one explicit time loop (time/explicit_loop.hpp); or, with
// a strain-rate history (Sec. 5.2.1, methodology 1), the specimen alone between two walls.
#pragma once
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "bar/material.hpp"
#include "bar/pulse.hpp"
#include "bar/specimen_column.hpp"
#include "dem/dem_specimen_params.hpp"
#include "fe/fe_specimen.hpp"
#include "shpb/strain_rate_history.hpp"

namespace kolsky::shpb {

/// characteristic: exact 1-D delay-line bars; sphere_chain: Sec. 4.3 ball chains; meshed: both
/// bars as axisymmetric FE meshes in one body with an FE specimen (fe/meshed_shpb.hpp).
enum class BarKind { characteristic, sphere_chain, meshed };

/// Mesh of meshed bars (BarKind::meshed only).
struct BarMeshSpec {
  int n_radial = 4;               ///< radial elements per bar
  double element_length = 2e-3;   ///< target axial element length, m
};

struct BarSpec {
  bar::BarMaterial material;
  bar::BarGeometry geometry;
  std::vector<double> gauges;  ///< gauge distances from the specimen face, m
  int n_spheres = 0;           ///< sphere-chain bars: ball count (0: L/(2R), Eq. 4.3)
};

struct TimeSpec {
  double end_time = 1.5e-3;     ///< s
  double dt = 0.0;              ///< s; 0 = safety_factor * stable dt
  /// Fraction of the assembly's raw stable dt the loop steps at: the one safety factor of a run
  /// (docs/architecture.md, "One time-step policy"); 0 = default_safety_factor(specimen).
  double safety_factor = 0.0;
  /// false lifts the dt limit (at planning and during the run, FE included) and the energy
  /// checks, only to exercise the detector of last resort: non-finite values (exit 3).
  bool check_stability = true;
  /// With dt = 0 and strain-rate walls: refine dt after a break lowers the limit (true), or
  /// plan for the smallest possible daughter from the first step (false, the default: the
  /// breakage statistics converge only at the up-front step, docs/breakage.md "Time step").
  /// The bar assemblies always plan up front.
  bool refine_after_breaks = false;
  /// Relative energy growth that counts as a blow-up. Scenes with strain-rate walls default to
  /// kWallsEnergyTolerance instead (set it so when building such a spec by hand).
  double energy_tolerance = 0.01;
};

/// The default time.energy_tolerance of strain-rate walls (Sec. 5.2.1). Their ledger is judged
/// against the wall work alone (a bar run judges against the whole injected pulse, of which the
/// specimen takes a part), and a Hertz-Mindlin packing with grain friction creates about 1 %
/// of that work at the start of loading by the non-potential part of Mindlin's
/// overlap-dependent k_t (dem_system.hpp, DemEnergy): measured 1.0-1.1 % on the ~250-grain
/// test specimen at 10-1200 /s, independent of dt (0.05 and 0.15 x the raw limit), 0.4 %
/// without grain friction. 5 % (the FE specimen's bound) leaves a factor 4.5 over it; an
/// unstable step grows the energy by orders of magnitude within tens of steps.
inline constexpr double kWallsEnergyTolerance = 0.05;

struct OutputSpec {
  double interval = 0.0;  ///< probe sampling interval, s; 0 = every 1 us rounded to steps
  double snapshot_interval = 0.0;  ///< DEM particle snapshots, s (rounded to steps); 0 = none
};

/// The specimen between the bars: a 1-D column (bar/), an axisymmetric FE mesh (fe/) or a
/// DEM packing (dem/).
using SpecimenSpec = std::variant<bar::ColumnParams, fe::FeSpecimenParams, dem::DemSpecimenParams>;
double specimen_length(const SpecimenSpec& s);    ///< L_s, m
double specimen_diameter(const SpecimenSpec& s);  ///< m
/// The default time.safety_factor: kDefaultSafetyFactor, times dem::kDemStepFraction (0.3) for
/// a DEM specimen, whose raw limit is the Rayleigh step of a single contact (dem_system.hpp):
/// 0.5 x 0.3 is the 0.15 kolsky's DEM runs have always stepped at (the same bits).
inline constexpr double kDefaultSafetyFactor = 0.5;
double default_safety_factor(const SpecimenSpec& s);

struct ExperimentSpec {
  std::string title;
  /// Set: methodology 1 of Sec. 5.2.1 (StrainRateWallsAssembly, strain_rate_walls.hpp): the
  /// specimen (DEM only) between an incident-side wall driven by this history and a fixed
  /// transmission-side wall; bar_kind, incident, transmission, bar_mesh and pulse are unused.
  /// Unset: the bars and the pulse load the specimen.
  std::optional<StrainRateHistory> strain_rate;
  /// With strain_rate set and > 0: the run ends, complete, at the first probe sample whose
  /// back-wall stress reaches this (Pa), before time.end. A test is loaded until a stress, not
  /// for a printed duration, when only that stress is known (Sec. 5.3.1 compares the Wang
  /// specimens at 72 MPa; reproductions/chapter5/README.md, H2). 0: time.end alone.
  double end_at_back_stress = 0.0;
  BarKind bar_kind = BarKind::characteristic;
  BarSpec incident, transmission;
  BarMeshSpec bar_mesh;
  bar::Pulse pulse = bar::TrapezoidPulse{};
  SpecimenSpec specimen = bar::ColumnParams{};
  /// A DEM specimen's tube as an FE mesh (specimen.tube = meshed): with bars.kind = meshed the
  /// FE-DEM coupling (coupling/fe_dem.hpp), with characteristic bars coupling::FeTube
  /// (coupling/fe_tube.hpp); unset: the grains' rigid cylinder (or its compliance).
  std::optional<fe::MeshedTube> dem_tube;
  TimeSpec time;
  OutputSpec output;
};

/// What the FE-DEM coupling (meshed bars around a dem specimen, docs/coupling.md) refuses,
/// as InputError("", key, rule); here, beside the spec, so that the scene reader can name the
/// scene file without linking the assemblies. Needs a dem specimen.
void check_fe_dem_supported(const ExperimentSpec& spec);
/// What an FE tube around a dem specimen between 1-D bars (coupling/fe_tube.hpp) refuses, the
/// same way: other bars than characteristic, strain-rate walls, a held or preloaded specimen,
/// breakage. Needs a dem specimen with spec.dem_tube set.
void check_fe_tube_supported(const ExperimentSpec& spec);

}  // namespace kolsky::shpb
