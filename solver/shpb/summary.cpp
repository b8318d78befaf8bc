#include "shpb/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kolsky::shpb {

nlohmann::json summarize(const FaceWaves& w, const SpecimenHistory& h) {
  nlohmann::json s;
  if (h.t.empty()) return s;
  const long n = static_cast<long>(h.t.size());
  const auto peak = [](const std::vector<double>& v) {
    double m = 0;
    for (double x : v) if (std::isfinite(x)) m = std::max(m, x);
    return m;
  };
  s["peak_stress_back_mpa"] = peak(h.stress_back) / 1e6;
  s["peak_stress_front_mpa"] = peak(h.stress_front) / 1e6;
  s["peak_strain"] = peak(h.strain);
  s["peak_strain_rate_per_s"] = peak(h.strain_rate);
  // A direct analysis (strain-rate walls, Sec. 5.2.1) has no waves: no wave energies, no
  // Eq. 1.4 residual. Its stress-strain curves are the back (transmitted) and the average
  // stress against Eq. 5.1's strain; their end points at the peak strain are reported.
  const bool waves = !h.w_incident.empty();
  if (!waves) {
    s["peak_stress_avg_mpa"] = peak(h.stress_avg) / 1e6;
    const auto at = std::max_element(h.strain.begin(), h.strain.end()) - h.strain.begin();
    s["sigma_back_at_peak_eps_mpa"] = h.stress_back[at] / 1e6;
    s["sigma_avg_at_peak_eps_mpa"] = h.stress_avg[at] / 1e6;
  }
  // Equilibrium: alpha below 0.05 (Sec. 2.4.2) for 5 consecutive samples.
  const long eq = first_equilibrium_index(h.alpha, 0.05, 5);
  s["equilibrium_time_us"] = eq >= 0 ? nlohmann::json(h.t[eq] * 1e6) : nlohmann::json(nullptr);
  const auto idx = waves ? equilibrium_indices(w, h, 0, n) : equilibrium_indices(h, 0, n);
  s["force_balance_fbc"] = idx.force_balance;
  s["stress_equilibrium_seqi"] = idx.stress_equilibrium;
  s["mean_alpha"] = idx.mean_alpha;
  if (!waves) return s;
  s["w_incident_j"] = h.w_incident.back();
  s["w_reflected_j"] = h.w_reflected.back();
  s["w_transmitted_j"] = h.w_transmitted.back();
  s["w_loss_j"] = h.w_loss.back();
  s["dissipation_percent"] = h.dissipation_percent.back();
  return s;
}

std::string format_summary(const nlohmann::json& s) {
  std::string out;
  for (const auto& [k, v] : s.items()) {
    char line[160];
    if (v.is_number())
      std::snprintf(line, sizeof line, "  %-26s %.6g\n", k.c_str(), v.get<double>());
    else
      std::snprintf(line, sizeof line, "  %-26s %s\n", k.c_str(), v.dump().c_str());
    out += line;
  }
  return out;
}

}  // namespace kolsky::shpb
