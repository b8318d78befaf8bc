#include "chapter4/calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/format.hpp"
#include "harness/root_search.hpp"

namespace kolsky::ch4 {

using repro::fmt;

double x_of_k(double k) { return k >= 1 ? -std::numeric_limits<double>::infinity() : std::log10(1 - k); }
double k_of_x(double x) { return 1 - std::pow(10.0, x); }

CalSettings cal_settings(const nlohmann::json& studies) {
  const auto& c = studies.at("rotational_calibration");
  CalSettings s;
  s.start_ks = c.at("start_ks").get<std::vector<double>>();
  s.resolution_rtol = c.at("resolution_rtol").get<double>();
  s.x_tolerance = c.at("x_tolerance").get<double>();
  s.max_evaluations = c.at("max_evaluations").get<int>();
  return s;
}

const CalPoint* Calibration::root() const {
  if (!std::isfinite(x)) return nullptr;
  for (const auto& p : points)
    if (p.x == x) return &p;
  return nullptr;
}

CalPoint cal_point(const CaseResult& c, const Measures& m, bool reused) {
  CalPoint p;
  p.k = c.rolling_factor;
  p.x = x_of_k(c.rolling_factor);
  p.value = m.modulus_initial;
  p.m = m;
  p.wall_s = reused ? 0 : c.wall_s;
  p.reused = reused;
  p.label = c.label;
  if (c.ok) {
    const long end = m.i_end > 0 ? m.i_end : static_cast<long>(c.history.t.size());
    p.strain.assign(c.history.strain.begin(), c.history.strain.begin() + end);
    p.stress.assign(c.history.stress_back.begin(), c.history.stress_back.begin() + end);
  }
  return p;
}

Calibration calibrate(const std::function<CalPoint(double k)>& evaluate, double target,
                      const CalSettings& s) {
  Calibration cal;
  cal.target = target;
  harness::RootSearchSettings rs;
  for (double k : s.start_ks) rs.start_x.push_back(x_of_k(k));
  rs.f_tolerance = s.resolution_rtol * std::abs(target);
  rs.x_tolerance = s.x_tolerance;
  rs.max_evaluations = s.max_evaluations;
  // f(x) = M(x) - target. A start point runs at its own k (the k -> x -> k round trip is not
  // exact), any other at k_of_x(x); the point keeps the finder's x exactly.
  auto f = [&](double x) {
    double k = k_of_x(x);
    for (size_t i = 0; i < s.start_ks.size(); ++i)
      if (rs.start_x[i] == x) k = s.start_ks[i];
    CalPoint p = evaluate(k);
    p.x = x;
    cal.points.push_back(p);
    return harness::RootEvaluation{p.value - target, !p.reused};
  };
  const harness::RootSearchResult r = harness::brent_root_search(f, rs);
  cal.bracketed = r.bracketed;
  cal.converged = r.converged;
  cal.x_lo = r.x_lo, cal.x_hi = r.x_hi, cal.slope = r.slope;
  cal.iterations = r.iterations, cal.evaluations = r.evaluations;
  if (!r.bracketed) {
    std::vector<const CalPoint*> sorted;
    for (const auto& p : cal.points)
      if (std::isfinite(p.x) && std::isfinite(p.value)) sorted.push_back(&p);
    std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->x < b->x; });
    std::string vals;
    for (const auto* p : sorted) vals += (vals.empty() ? "" : ", ") + fmt("%.1f MPa at k = ", p->value / 1e6) + fmt("%.8g", p->k);
    cal.status = "no root: the target " + fmt("%.1f MPa", target / 1e6) + " is not bracketed by the start points (" + vals + ")";
    return cal;
  }
  cal.dx = s.resolution_rtol * std::abs(target) / std::abs(cal.slope);
  cal.x = r.x;
  using End = harness::RootSearchResult::End;
  const std::string after = " after " + std::to_string(cal.iterations) + " Brent iteration(s)";
  switch (r.end) {
    case End::f_tolerance:
      cal.status = "converged: |M - target| = " + fmt("%.1f MPa", std::abs(cal.root()->value - target) / 1e6) +
                   " <= resolution " + fmt("%.1f MPa", rs.f_tolerance / 1e6) + after;
      break;
    case End::x_tolerance:
      cal.status = "converged: bracket [" + fmt("%.3f", r.final_lo) + ", " + fmt("%.3f", r.final_hi) + "] narrower than " +
                   fmt("%g decades", s.x_tolerance) + after;
      break;
    case End::budget_spent: cal.status = "evaluation budget (" + std::to_string(s.max_evaluations) + ") spent"; break;
    case End::non_finite:
      cal.status = "no initial modulus at k = " + fmt("%.10g", cal.points.back().k) + " (" + cal.points.back().label + ")";
      break;
    case End::gsl_error: cal.status = "GSL: " + r.gsl_message; break;
    case End::no_bracket: break;
  }
  // A converged root is the finder's x (k from x); after a failure, the best point's own k.
  const CalPoint* at = cal.root();
  cal.k = r.converged || at == nullptr ? k_of_x(cal.x) : at->k;
  return cal;
}

std::string calibration_table(const Calibration& c) {
  std::string t =
      "| # | k per 1 ns | x = log10(1 - k) | M 1-3 MPa | M 7-10 MPa | M 1-10 MPa | case wall (s) | |\n"
      "|---|---|---|---|---|---|---|---|\n";
  int i = 0;
  for (const auto& p : c.points) {
    t += "| " + std::to_string(++i) + " | " + fmt("%.8g", p.k) + " | " + fmt("%.3f", p.x) + " | " +
         fmt("%.1f MPa", p.value / 1e6) + " | " + fmt("%.1f MPa", p.m.modulus_late / 1e6) + " | " +
         fmt("%.1f MPa", p.m.modulus_back / 1e6) + " | " + (p.reused ? "(reused)" : fmt("%.1f", p.wall_s)) + " | " +
         (p.x == c.x ? "**root**" : "") + " |\n";
  }
  return t;
}

}  // namespace kolsky::ch4
