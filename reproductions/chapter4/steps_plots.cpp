// Step 9 of the Chapter 4 recipe: the plots of the printed case and of the rotational family
// (t = 0: incident arrival; curves to the first 10 MPa back-stress sample, Sec. 4.4.1's limit).
#include "chapter4/recipe.hpp"

namespace kolsky::ch4 {

// 9. sigma_t and sigma_avg against strain with Song et al.'s 228 MPa (Sec. 4.4.1), alpha(t)
// against the 0.05 of equilibrium (Eq. 4.15), and the family's curves (Sec. 4.4.2).
void case_plots(Recipe& r) {
  const auto& base = r.printed();
  const auto& h = base.history;
  const long n = r.printed_end();
  harness::Plot ss{"stress_strain.png", "Stress vs strain to 10 MPa back stress (Eqs. 1.1, 1.2, 4.16)", "strain (-)", "stress (MPa)", {}, {}, {}};
  ss.series = {{"sigma_t (bar waves)", scaled(h.strain, 1, n), scaled(h.stress_back, 1e-6, n)},
               {"sigma_avg (bar waves)", scaled(h.strain, 1, n), scaled(h.stress_avg, 1e-6, n), "dashed"}};
  long nif = 0;
  while (nif < static_cast<long>(base.faces.back.size()) && base.faces.back[nif] < r.limit) ++nif;
  ss.series.push_back({"back wall (interface)", scaled(base.faces.strain, 1, nif), scaled(base.faces.back, 1e-6, nif), "dashed"});
  const double e_max = n > 0 ? h.strain[n - 1] : 0.05;
  ss.bands = {{"228 MPa (Song 2009, Sec. 4.4.1)", {0, e_max}, {0, 0.228e3 * e_max * 0.95}, {0, 0.228e3 * e_max * 1.05}}};
  harness::Plot ap{"alpha.png", "alpha(t), Eq. 4.15, to 10 MPa back stress", "t (us)", "alpha (-)", {}, {}, {}};
  ap.series = {{"alpha (bar waves)", scaled(h.t, 1e6, n), scaled(h.alpha, 1, n)},
               {"0.05", {0, n > 0 ? h.t[n - 1] * 1e6 : 1}, {r.threshold, r.threshold}, "dashed"}};
  ap.logy = true;
  harness::Plot rp{"rotation.png", "Rotational resistance family: sigma_t vs strain (Sec. 4.4.2)", "strain (-)", "stress (MPa)", {}, {}, {}};
  harness::Plot rt{"rotation_back_stress.png", "Back-face (interface) stress vs time, rotational family", "t (us)", "stress (MPa)", {}, {}, {}};
  harness::Plot ra{"rotation_alpha.png", "alpha(t) of the rotational family", "t (us)", "alpha (-)", {}, {}, {}};
  ra.logy = true;
  for (size_t i = 0; i < r.cases.size(); ++i) {
    const auto& c = r.cases[i];
    if (!c.ok) continue;
    const long ni = r.ms[i].i_end > 0 ? r.ms[i].i_end : static_cast<long>(c.history.t.size());
    rp.series.push_back({c.label, scaled(c.history.strain, 1, ni), scaled(c.history.stress_back, 1e-6, ni)});
    rt.series.push_back({c.label, scaled(c.faces.t, 1e6), scaled(c.faces.back, 1e-6)});
    ra.series.push_back({c.label, scaled(c.history.t, 1e6, ni), scaled(c.history.alpha, 1, ni)});
  }
  r.rep.plots = {ss, ap, rp, rt, ra};
}

}  // namespace kolsky::ch4
