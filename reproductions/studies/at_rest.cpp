// study_at_rest: does a prepared DEM specimen stay at rest? (issue 31, item 0; docs/dem.md,
// "A specimen at rest"). Builds a scene's DEM specimen exactly as a run does (packing through
// the cache, pre-stress, the optional relaxation to rest), then steps it with both end walls
// and the tube fixed and no load, and prints the coordination number, the wall stresses and
// the grains' kinetic energy against time. A specimen in equilibrium under the run's own law
// keeps them; one held by forces the run's law does not have falls apart.
//   study_at_rest SCENE.json [--relax on|off|scene] [--hold 200e-6] [--every 10e-6]
//                 [--cache DIR] [--upscale N] [--csv OUT.csv]
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/case_pipeline.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "dem/dem_specimen_params.hpp"
#include "dem/packing.hpp"
#include "scene/scene.hpp"
#include "studies/study_cli.hpp"

namespace {

using namespace kolsky;

struct Options {
  std::string scene, relax = "scene", cache, csv;
  double hold = 200e-6, every = 10e-6, upscale = 0, rolling = -1, diameter = 0, length = 0;
  int relax_steps = 0;
  std::vector<std::string> sets;  // --set dotted.key=JSON
};

[[noreturn]] void usage(int code) {
  repro::exit_with_usage(code,
                         "usage: study_at_rest SCENE.json [--relax on|off|scene] [--hold S] [--every S]\n"
                         "                     [--cache DIR] [--upscale N] [--csv OUT.csv] [--relax-steps K]\n"
                         "                     [--rolling K] [--diameter M] [--length M]\n"
                         "                     [--set dotted.key=JSON ...]  (e.g. specimen.packing='\"servo_walls\"')\n"
                         "Steps the scene's DEM specimen with fixed walls and no load; prints Z, wall\n"
                         "stresses and kinetic energy every --every seconds up to --hold (default 200 us).\n");
}

Options parse(int argc, char** argv) {
  Options o;
  repro::read_flags(argc, argv, usage, [&](const std::string& a, repro::FlagReader& r) {
    if (a == "--relax") o.relax = r.value();
    else if (a == "--hold") o.hold = r.number();
    else if (a == "--every") o.every = r.number();
    else if (a == "--cache") o.cache = r.value();
    else if (a == "--upscale") o.upscale = r.number();
    else if (a == "--csv") o.csv = r.value();
    else if (a == "--relax-steps") o.relax_steps = static_cast<int>(r.integer());
    else if (a == "--set") o.sets.push_back(r.value());
    else if (a == "--rolling") o.rolling = r.number();
    else if (a == "--diameter") o.diameter = r.number();
    else if (a == "--length") o.length = r.number();
    else if (o.scene.empty() && a[0] != '-') o.scene = a;
    else return false;
    return true;
  });
  if (o.scene.empty() || !(o.relax == "on" || o.relax == "off" || o.relax == "scene")) usage(1);
  return o;
}

struct Reading {
  double t, z, sigma_zz, sigma_rr, kinetic, elastic, z_load_bearing, rattlers;
};

Reading read(const dem::DemSpecimen& s, double t) {
  const dem::DemSystem& sys = s.system();
  const double n = static_cast<double>(sys.particles().size());
  const double r = 0.5 * std::sqrt(s.area() / std::numbers::pi * 4);  // tube radius
  const double szz = 0.5 * (sys.plane_force(s.front_plane()) + sys.plane_force(s.back_plane())) / s.area();
  const double srr = sys.cylinder_force(0) / (2 * std::numbers::pi * r * s.length());
  const dem::DemEnergy e = sys.energy();
  const auto [z_lb, rattlers] = dem::coordination_without_rattlers(sys.particles(), 2 * r, s.length());
  return {t, 2.0 * static_cast<double>(sys.n_contacts()) / n, szz, srr, e.kinetic, e.elastic,
          z_lb, rattlers};
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    std::ifstream f(o.scene);
    if (!f) throw std::runtime_error("cannot read " + o.scene);
    nlohmann::json j = nlohmann::json::parse(f);
    if (!o.cache.empty()) j["specimen"]["packing_cache"] = std::filesystem::absolute(o.cache).string();
    if (o.upscale > 0) j["specimen"]["upscale"] = o.upscale;
    if (o.relax != "scene") j["specimen"]["relax_to_rest"] = o.relax == "on";
    if (o.rolling >= 0) j["specimen"]["rolling_factor"] = o.rolling;
    if (o.diameter > 0) j["specimen"]["diameter"] = o.diameter;
    if (o.length > 0) j["specimen"]["length"] = o.length;
    for (const std::string& s : o.sets) harness::apply_change(j, harness::parse_change(s, "--set"), o.scene);
    const std::string dir = std::filesystem::path(o.scene).parent_path().string();
    auto sc = scene::parse_scene(j, o.scene, dir);
    auto& dp = std::get<dem::DemSpecimenParams>(sc.spec.specimen);
    dp.walls.hold_until_loaded = false;  // stepped here from t = 0
    if (dp.rest && o.relax_steps > 0) dp.rest->max_steps = o.relax_steps;
    dem::DemSpecimen s = dem::make_dem_specimen(dp);
    if (const auto& r = s.rest_relaxation())
      std::printf("relaxation to rest: %d steps, %d quenches, %s (KE/elastic %.2e), Z %.3f -> %.3f, "
                  "elastic %.3e -> %.3e J\n",
                  r->steps, r->quenches, r->converged ? "converged" : "NOT converged",
                  r->kinetic_to_elastic, r->coordination_before, r->coordination_after,
                  r->elastic_before, r->elastic_after);
    dem::DemSystem& sys = s.coupled_system();
    {  // Whole cylinder against its interior (issue 31, H1: the loose layer at the walls)
      const auto& g = sys.particles();
      double d_mean = 0;
      for (double r : g.radius) d_mean += 2 * r / g.size();
      const double D = dp.packing.diameter, L = dp.packing.length;
      std::printf("porosity (1e6 samples, +-5e-4): whole %.4f, interior %.4f (1 mean diameter from the walls), "
                  "%.4f (2); mean diameter %.3g m\n",
                  dem::interior_porosity(g, D, L, 0.0), dem::interior_porosity(g, D, L, d_mean),
                  dem::interior_porosity(g, D, L, 2 * d_mean), d_mean);
    }
    const double dt = dem::kDemStepFraction * sys.stable_dt();
    std::printf("%zu grains, dt %.3e s, hold %.0f us\n", sys.particles().size(), dt, o.hold * 1e6);
    std::string table =
        "t_s,coordination,sigma_zz_Pa,sigma_rr_Pa,kinetic_J,elastic_J,z_load_bearing,rattlers\n";
    std::printf("%8s %8s %12s %12s %12s %12s %8s %9s\n", "t (us)", "Z", "s_zz (kPa)", "s_rr (kPa)",
                "KE (J)", "elastic (J)", "Z_lb", "rattlers");
    auto report = [&](const Reading& q) {
      std::printf("%8.1f %8.3f %12.3f %12.3f %12.3e %12.3e %8.3f %9.3f\n", q.t * 1e6, q.z,
                  q.sigma_zz / 1e3, q.sigma_rr / 1e3, q.kinetic, q.elastic, q.z_load_bearing,
                  q.rattlers);
      std::fflush(stdout);
      char line[256];
      std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", q.t, q.z,
                    q.sigma_zz, q.sigma_rr, q.kinetic, q.elastic, q.z_load_bearing, q.rattlers);
      table += line;
    };
    report(read(s, 0));
    double t = 0, next = o.every;
    while (t < o.hold * (1 - 1e-12)) {
      sys.step(dt);
      t += dt;
      if (t >= next * (1 - 1e-12)) {
        report(read(s, t));
        next += o.every;
      }
    }
    if (!o.csv.empty()) write_file_atomic(o.csv, table);
    return 0;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "study_at_rest: %s\n", e.what());
    return 1;
  }
}
