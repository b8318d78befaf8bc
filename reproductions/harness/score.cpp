// Scoring of measurements against targets (rules in score.hpp and docs/reproductions.md).
#include "harness/score.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace kolsky::harness {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void append(std::string& note, const std::string& text) {
  if (text.empty()) return;
  note += (note.empty() ? "" : "; ") + text;
}

/// Closest approach of the measured polyline to y_r within x in [a, b].
struct Nearest {
  double error = kInf, x = 0.0, y = 0.0;
  void offer(double err, double xq, double yq) {
    if (err < error) std::tie(error, x, y) = std::tie(err, xq, yq);
  }
};

Nearest nearest_in_window(const Curve& c, double y_r, double a, double b) {
  Nearest best;
  for (size_t i = 0; i < c.x.size(); ++i)
    if (c.x[i] >= a && c.x[i] <= b) best.offer(std::abs(c.y[i] - y_r), c.x[i], c.y[i]);
  for (size_t i = 0; i + 1 < c.x.size(); ++i) {
    const double x0 = c.x[i], x1 = c.x[i + 1], y0 = c.y[i], y1 = c.y[i + 1];
    const double lo = std::max(std::min(x0, x1), a), hi = std::min(std::max(x0, x1), b);
    if (lo > hi) continue;
    // The segment restricted to [lo, hi] spans y between its clipped end values, so y_r is
    // either crossed (error 0) or closest at one of those ends.
    const auto y_at = [&](double xq) { return x1 == x0 ? y0 : y0 + (y1 - y0) * (xq - x0) / (x1 - x0); };
    const double ya = x1 == x0 ? y0 : y_at(lo), yb = x1 == x0 ? y1 : y_at(hi);
    if ((ya - y_r) * (yb - y_r) <= 0.0) {
      const double xc = (yb == ya) ? lo : lo + (hi - lo) * (y_r - ya) / (yb - ya);
      best.offer(0.0, xc, y_r);
    } else {
      best.offer(std::abs(ya - y_r), lo, ya);
      best.offer(std::abs(yb - y_r), hi, yb);
    }
  }
  return best;
}

/// Ordering key for "worst": a point outside the measured range beats any error, then the
/// error relative to what is allowed, then the raw error.
std::tuple<bool, double, double> badness(const WorstPoint& w) {
  const double ratio = w.allowed > 0.0 ? w.error / w.allowed : (w.error > 0.0 ? kInf : 0.0);
  return {w.outside, ratio, w.error};
}

}  // namespace

// ---- Measurements ----

void Measurements::add(const std::string& id, Measurement m) {
  if (!values_.emplace(id, std::move(m)).second)
    throw std::invalid_argument("measurement '" + id + "' recorded twice");
}

void Measurements::scalar(const std::string& id, double value) {
  Measurement m;
  m.kind = Kind::scalar;
  m.value = value;
  add(id, std::move(m));
}

void Measurements::trend(const std::string& id, bool holds, std::string what) {
  Measurement m;
  m.kind = Kind::trend;
  m.holds = holds;
  m.what = std::move(what);
  add(id, std::move(m));
}

void Measurements::curve(const std::string& id, Curve measured) {
  Measurement m;
  m.kind = Kind::curve;
  m.curve = std::move(measured);
  add(id, std::move(m));
}

void Measurements::note(const std::string& id, std::string text) { append(notes_[id], text); }

void Measurements::merge(const Measurements& other) {
  for (const auto& [id, m] : other.values_) add(id, m);
  for (const auto& [id, text] : other.notes_) append(notes_[id], text);
}

const Measurement* Measurements::find(const std::string& id) const {
  const auto it = values_.find(id);
  return it == values_.end() ? nullptr : &it->second;
}

std::string Measurements::note_for(const std::string& id) const {
  const auto it = notes_.find(id);
  return it == notes_.end() ? "" : it->second;
}

// ---- curves ----

CurveCheck compare_curve(const Curve& measured, const Curve& reference, const Tolerance& tol) {
  CurveCheck cc;
  if (measured.x.size() != measured.y.size()) {
    cc.problem = "measured curve has " + std::to_string(measured.x.size()) + " x but " +
                 std::to_string(measured.y.size()) + " y values";
    return cc;
  }
  if (measured.x.empty()) {
    cc.problem = "measured curve is empty";
    return cc;
  }
  for (size_t i = 0; i < measured.x.size(); ++i)
    if (!std::isfinite(measured.x[i]) || !std::isfinite(measured.y[i])) {
      cc.problem = "measured curve is not finite at sample " + std::to_string(i);
      return cc;
    }
  const auto [xmin, xmax] = std::minmax_element(measured.x.begin(), measured.x.end());
  for (size_t i = 0; i < reference.x.size(); ++i) {
    WorstPoint w;
    w.x_ref = reference.x[i];
    w.y_ref = reference.y[i];
    w.allowed = tol.atol + tol.rtol * std::abs(w.y_ref);
    const double a = w.x_ref - tol.xtol, b = w.x_ref + tol.xtol;
    if (b < *xmin || a > *xmax) {
      w.outside = true;
      w.error = kInf;
      w.x_nearest = w.y_nearest = std::numeric_limits<double>::quiet_NaN();
    } else {
      const Nearest n = nearest_in_window(measured, w.y_ref, a, b);
      std::tie(w.error, w.x_nearest, w.y_nearest) = std::tie(n.error, n.x, n.y);
    }
    if (w.outside || !(w.error <= w.allowed)) ++cc.n_failed;
    if (!cc.worst || badness(w) > badness(*cc.worst)) cc.worst = w;
  }
  cc.pass = cc.n_failed == 0 && !reference.x.empty();
  if (reference.x.empty()) cc.problem = "reference curve has no points";
  return cc;
}

// ---- scoring ----

bool Score::fails_set() const { return !pass && target->status == Status::expected_pass; }

namespace {

/// Accepted interval of a scalar: the band, or the reference widened by its tolerance.
Band scalar_interval(const Target& t) {
  if (t.band) return *t.band;
  const Tolerance& tol = *t.tolerance;
  const auto width = [&](double ref) { return tol.atol + tol.rtol * std::abs(ref); };
  const double rlo = t.reference.value ? *t.reference.value : t.reference.range->lo;
  const double rhi = t.reference.value ? *t.reference.value : t.reference.range->hi;
  return {rlo - width(rlo), rhi + width(rhi)};
}

void score_scalar(const Measurement& m, Score& s) {
  if (!std::isfinite(m.value)) {
    append(s.note, "measured value is not finite");
    return;
  }
  s.value = m.value;
  s.pass = *s.lo <= m.value && m.value <= *s.hi;
}

void score_curve(const Target& t, const Measurement& m, Score& s) {
  const CurveCheck cc = compare_curve(m.curve, t.reference.points, *t.tolerance);
  s.pass = cc.pass;
  if (!cc.problem.empty()) {
    append(s.note, cc.problem);
    return;
  }
  const WorstPoint& w = *cc.worst;
  s.worst = w;
  const std::string n_ref = std::to_string(t.reference.points.x.size());
  if (w.outside) {
    const auto [xmin, xmax] = std::minmax_element(m.curve.x.begin(), m.curve.x.end());
    append(s.note, "reference point x = " + fmt(w.x_ref) + " lies outside the measured x range [" +
                       fmt(*xmin) + ", " + fmt(*xmax) + "] (xtol " + fmt(t.tolerance->xtol) + ")");
  } else if (w.y_ref != 0.0) {
    s.value = w.error / std::abs(w.y_ref);
    s.lo = 0.0;
    s.hi = w.allowed / std::abs(w.y_ref);
    append(s.note, "value = relative error |y - y_ref|/|y_ref| at the worst of " + n_ref +
                       " reference points (x = " + fmt(w.x_ref) +
                       "); hi = (atol + rtol*|y_ref|)/|y_ref| there");
  } else {
    s.value = w.error;
    s.lo = 0.0;
    s.hi = w.allowed;
    append(s.note, "value = absolute error at the worst of " + n_ref + " reference points (x = " +
                       fmt(w.x_ref) + ", where y_ref = 0, so no relative error), in " + t.unit);
  }
  if (cc.n_failed > 0)
    append(s.note, std::to_string(cc.n_failed) + " of " + n_ref + " reference points out of tolerance");
}

}  // namespace

Score score_target(const Target& t, const Measurements& m) {
  Score s;
  s.target = &t;
  if (t.kind == Kind::trend) s.lo = s.hi = 1.0;
  if (t.kind == Kind::scalar) {
    const Band b = scalar_interval(t);
    s.lo = b.lo;
    s.hi = b.hi;
  }
  const Measurement* meas = m.find(t.id);
  if (meas == nullptr) {
    append(s.note, "not measured");
  } else if (meas->kind != t.kind) {
    s.measured = true;
    append(s.note, "recorded as a " + to_string(meas->kind) + " but the target is a " +
                       to_string(t.kind));
  } else {
    s.measured = true;
    switch (t.kind) {
      case Kind::scalar: score_scalar(*meas, s); break;
      case Kind::trend:
        s.value = meas->holds ? 1.0 : 0.0;
        s.pass = meas->holds;
        append(s.note, meas->what);
        break;
      case Kind::curve: score_curve(t, *meas, s); break;
    }
  }
  if (t.status == Status::known_deviation) {
    s.unexpected_pass = s.pass;
    append(s.note, s.pass ? "passes although declared known_deviation: remove the note from "
                            "targets.json and make it expected_pass"
                          : "known deviation: " + t.reason);
  }
  append(s.note, m.note_for(t.id));
  return s;
}

}  // namespace kolsky::harness
