// Step 13 of the Chapter 4 recipe: the report's preamble (the scene, the packing, the initial
// interface stresses) ahead of the tables of steps 4 to 11, and the report scored.
#include <cstdio>

#include "chapter4/recipe.hpp"

namespace kolsky::ch4 {

using repro::fmt;

namespace {

std::string packing_note(const Recipe& r) {
  const auto& P = r.packing.result;
  return "**Packing** (" + std::string(r.packing.from_cache ? "read from the cache" : "generated") + fmt(" in %.1f s", r.pack_s) +
         "): " + std::to_string(P.count) + " grains (expected " + fmt("%.0f", P.expected_count) + "), porosity " +
         fmt("%.4f", P.porosity) + ", Z " + fmt("%.2f", P.coordination) + " (without rattlers " +
         fmt("%.2f", P.coordination_no_rattlers) + ", rattlers " + fmt("%.0f %%", 100 * P.rattler_fraction) +
         "), largest overlap " + fmt("%.2g", P.max_overlap) + " x mean radius, residual Hertz mean stress " +
         fmt("%.3g kPa", P.mean_stress_hertz / 1e3) + (P.settled ? "" : " (settling stopped at the stage cap)") +
         (P.prestress_stages > 0
              ? fmt("; pre-stressed (docs/dem.md, Pre-stress) to a wall mean stress of %.3g kPa", P.mean_stress / 1e3) +
                    fmt(" (radius factor %.6f, ", P.prestress_scale) + std::to_string(P.prestress_stages) +
                    " servo intervals, " + (P.prestress_converged ? "converged" : "NOT converged") + ")"
              : std::string());
}

}  // namespace

// 13. The sphere-chain bars carry the packing's wall forces from the start (held until the
// release), so the preamble gives them: the comparison window starts above them (Sec. 4.4.1).
int write_report(Recipe& r, double wall_s) {
  const auto& base = r.printed();
  r.rep.preamble_markdown = r.override_note +
      "Scene: `reproductions/chapter4/scene_" + r.args.scale + ".json` (DEM specimen, N = " + fmt("%g", r.upscale) +
      ", sphere-chain bars 216/108 balls as Table 4.1 prints, reconstructed 480/s pulse and grain-size curve). "
      "Interface stresses are the wall forces / specimen area (probes `stress_front`, `stress_back`); sigma_t, "
      "sigma_avg and alpha come from the bar waves at the faces (Eqs. 1.1, 1.2, 4.15, 4.16). The grains are held "
      "as packed until the incident wave reaches the specimen (`specimen.hold_until_loaded`, docs/dem.md).\n\n" +
      packing_note(r) +
      ".\n\nInitial interface stresses (the packing's wall forces / area, held until the release; with "
      "`specimen.preload_on_supports` the bars and these probes carry only the change from the preload): front " +
      (base.faces.front.empty() ? std::string("-") : fmt("%.3f MPa", base.faces.front.front() / 1e6)) + ", back " +
      (base.faces.back.empty() ? std::string("-") : fmt("%.3f MPa", base.faces.back.front() / 1e6)) +
      ". The comparison window starts at a back stress of 1 MPa, above this pre-stress and the sphere chain's ringing "
      "(sigma_t is not zeroed before the arrival).\n\n**Cases**\n\n" + r.family_md + r.twin_md + r.cal_md + r.jam_md +
      r.upscaling_md + r.scatter_md;
  r.rep.wall_time_s = wall_s;
  const int failed = harness::write_report(r.rep);
  std::printf("reproduce_chapter4 (%s): %d expected target(s) failed; report in %s/report.md (%.1f s)\n",
              r.args.scale.c_str(), failed, r.args.out_dir.c_str(), r.rep.wall_time_s);
  return failed == 0 ? 0 : 1;
}

}  // namespace kolsky::ch4
