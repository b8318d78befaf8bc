// Initial phase volumes and parameter validation (see three_phase_params.hpp).
#include "eos/three_phase_params.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace kolsky::eos {
namespace {

void require(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) throw std::invalid_argument(field + ": " + rule);
}

void check_tait(const TaitEos& e, const std::string& name) {
  require(std::isfinite(e.rho0) && e.rho0 > 0.0, name + ".rho0", "must be > 0");
  require(std::isfinite(e.c0) && e.c0 > 0.0, name + ".c0", "must be > 0");
  require(std::isfinite(e.k) && e.k > 0.0, name + ".k", "must be > 0");
  require(std::isfinite(e.p0), name + ".p0", "must be finite");
}

}  // namespace

double saturation_water_content(double porosity, double rho_solid, double rho_water) {
  return porosity * rho_water / ((1.0 - porosity) * rho_solid);
}

PhaseVolumes initial_volumes(double porosity, double water_content, double rho_solid,
                             double rho_water) {
  require(std::isfinite(porosity) && porosity > 0.0 && porosity < 1.0, "porosity",
          "must lie in (0, 1)");
  require(std::isfinite(water_content) && water_content >= 0.0, "water_content", "must be >= 0");
  PhaseVolumes v;
  v.solid = 1.0 - porosity;
  v.water = water_content * rho_solid / rho_water * v.solid;  // mass ratio -> volume ratio
  v.air = porosity - v.water;
  require(v.air >= 0.0, "water_content",
          "exceeds saturation (" +
              std::to_string(100.0 * saturation_water_content(porosity, rho_solid, rho_water)) +
              " % at porosity " + std::to_string(porosity) + ")");
  return v;
}

void validate(const ThreePhaseParams& p) {
  check_tait(p.water, "water");
  check_tait(p.solid, "solid");
  require(std::isfinite(p.air.p0) && p.air.p0 > 0.0, "air.p0", "must be > 0");
  require(std::isfinite(p.air.rho0) && p.air.rho0 > 0.0, "air.rho0", "must be > 0");
  require(std::isfinite(p.air.k) && p.air.k > 0.0, "air.k", "must be > 0");
  require(std::isfinite(p.friction) && p.friction >= 0.0, "friction", "must be >= 0");
  require(std::isfinite(p.k_p) && p.k_p >= 0.0, "k_p", "must be >= 0");
  require(std::isfinite(p.e_o) && p.e_o >= 0.0, "e_o", "must be >= 0");
  require(std::isfinite(p.b), "b", "must be finite");
  initial_volumes(p.porosity, p.water_content, p.solid.rho0, p.water.rho0);
}

}  // namespace kolsky::eos
