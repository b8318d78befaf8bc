// The Song et al. (2009) bar set-up of Sec. 2.2 (IB 4100 mm, TB 2440 mm, 19.1 mm steel bars,
// specimen 9.3 x 19.1 mm) as an ExperimentSpec, for verification cases built in code.
#pragma once
#include "shpb/experiment.hpp"

namespace kolsky::verify {

inline shpb::ExperimentSpec song_spec(const bar::ColumnMaterial& material) {
  shpb::ExperimentSpec s;
  s.title = "Song et al. (2009) set-up";
  s.incident.geometry = {4.1, 0.0191};
  s.transmission.geometry = {2.44, 0.0191};
  s.incident.gauges = {2.05};
  s.transmission.gauges = {0.5};
  bar::ColumnParams c;
  c.length = 0.0093;
  c.diameter = 0.0191;
  c.density = 1457.5;  // porosity 0.45 x 2650 kg/m^3 solids (Sec. 2.2, G_s = 2.65)
  c.n_elements = 50;
  c.material = material;
  s.specimen = c;
  s.pulse = bar::TrapezoidPulse{100e6, 100e-6, 500e-6, 100e-6, 0.0};
  s.time.end_time = 1.6e-3;
  s.output.interval = 0.5e-6;
  return s;
}

/// The column parameters of a spec built by song_spec (to adjust them).
inline bar::ColumnParams& column(shpb::ExperimentSpec& s) {
  return std::get<bar::ColumnParams>(s.specimen);
}

}  // namespace kolsky::verify
