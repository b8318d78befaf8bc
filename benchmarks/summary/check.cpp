// bench-check's comparison and the spread measurement behind its margins (see report.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "summary/report.hpp"

namespace kolsky::benchsum {
namespace {

std::string pad(std::string s, std::size_t w) {
  if (s.size() < w) s.append(w - s.size(), ' ');
  return s;
}

/// The label of a kernel's results ("pack_35k", or the Song packing when pack_35k is absent).
std::string label_of(const ResultFile& f, const std::string& key) {
  for (const Entry& e : f.entries)
    if (e.key == key && !e.label.empty()) return e.label;
  return "";
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

std::vector<CheckRow> compare(const std::vector<ResultFile>& tracked_files, const std::vector<ResultFile>& runs,
                              const std::map<std::string, double>& margins) {
  std::vector<CheckRow> rows;
  for (const Tracked& t : tracked()) {
    for (const ResultFile& run : runs) {
      const auto now = ratio(run, t);
      if (!now) continue;
      const auto m = margins.find(t.id);
      if (m == margins.end()) throw std::invalid_argument("no margin given for " + t.id + " (--margin " + t.id + "=F)");
      CheckRow row{t, now, std::nullopt, "", "", m->second, false, ""};
      if (!usable(run, t)) {
        const auto c = two_core_factor(run);
        row.skipped = "second core busy: BM_Reference 2 / 1 threads = " + (c ? fmt("%.2f", *c) : std::string("?")) +
                      " < " + fmt("%.1f", kMinTwoCoreFactor);
      }
      long long base_time = 0;
      for (const ResultFile& f : tracked_files) {  // the newest with a ratio of the same version
        const auto r = ratio(f, t);
        const std::string label = label_of(f, t.kernel), run_label = label_of(run, t.kernel);
        const bool same_input = label.empty() || run_label.empty() || label == run_label;
        if (r && usable(f, t) && same_input && r->version == now->version && (!row.base || f.time >= base_time)) {
          row.base = r;
          base_time = f.time;
          row.base_file = f.name;
          row.base_date = short_date(f.time);
        }
      }
      row.regression = row.base && row.skipped.empty() && now->ratio < row.base->ratio * (1 - row.margin);
      rows.push_back(row);
    }
  }
  return rows;
}

std::string format_check(const std::vector<CheckRow>& rows) {
  std::string s = pad("figure", 33) + pad("tracked", 10) + pad("this run", 10) + pad("change", 9) + pad("allowed", 9) +
                  pad("result", 15) + "tracked file (date UTC)\n";
  for (const CheckRow& r : rows) {
    s += pad(r.figure.title, 33);
    if (!r.base) {
      s += pad("none", 10) + pad(fmt("%.5f", r.now->ratio), 10) + pad("", 9) + pad(fmt("-%.0f %%", 100 * r.margin), 9) +
           pad("no tracked value", 15) + "(none with reference v" + std::to_string(r.now->version) + ")\n";
      continue;
    }
    const double change = r.now->ratio / r.base->ratio - 1;
    s += pad(fmt("%.5f", r.base->ratio), 10) + pad(fmt("%.5f", r.now->ratio), 10) + pad(fmt("%+.1f %%", 100 * change), 9) +
         pad(fmt("-%.0f %%", 100 * r.margin), 9) +
         pad(!r.skipped.empty() ? "not compared" : r.regression ? "SLOWER (fail)" : "ok", 15) + r.base_file + " (" +
         r.base_date + ")\n";
  }
  for (const CheckRow& r : rows)
    if (!r.skipped.empty()) s += "\n" + r.figure.title + ": not compared, " + r.skipped + "\n";
  s += "\nrates behind the ratios (kernel / BM_Reference, millions per second):\n";
  for (const CheckRow& r : rows) {
    s += "  " + pad(r.figure.title, 32) + pad(r.figure.cpu_time ? "per CPU s " : "per wall s", 12) + "this run " +
         fmt("%.3f", r.now->kernel / 1e6) + " / " + fmt("%.1f", r.now->reference / 1e6);
    if (r.base)
      s += ",  tracked " + fmt("%.3f", r.base->kernel / 1e6) + " / " + fmt("%.1f", r.base->reference / 1e6);
    s += "\n";
  }
  return s;
}

std::string format_spread(const std::vector<ResultFile>& runs) {
  std::string s;
  for (const Tracked& t : tracked()) {
    std::vector<double> ratios, kernels, refs;
    for (const ResultFile& f : runs)
      if (const auto r = ratio(f, t)) {
        ratios.push_back(r->ratio);
        kernels.push_back(r->kernel);
        refs.push_back(r->reference);
      }
    if (ratios.empty()) continue;
    s += t.title + " (" + std::to_string(ratios.size()) + " runs; rates per " + (t.cpu_time ? "CPU" : "wall") +
         " second)\n";
    const auto line = [&](const std::string& what, const std::vector<double>& v, double scale, const char* f) {
      const double med = median(v);
      const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
      std::string l = "  " + pad(what, 16);
      for (double x : v) l += pad(fmt(f, x * scale), 9);
      return l + " median " + fmt(f, med * scale) + ", range " + fmt("%.1f", 100 * (*hi - *lo) / med) +
             " % of the median, lowest " + fmt("%.1f", 100 * (1 - *lo / med)) + " % below it\n";
    };
    s += line("ratio", ratios, 1.0, "%.5f");
    s += line("kernel M/s", kernels, 1e-6, "%.3f");
    s += line("reference M/s", refs, 1e-6, "%.2f");
  }
  std::string cores;
  for (const ResultFile& f : runs)
    if (const auto c = two_core_factor(f)) cores += " " + fmt("%.2f", *c);
  if (!cores.empty()) s += "BM_Reference 2 threads / 1 thread, per run:" + cores + "\n";
  return s.empty() ? "no run has a tracked ratio (kernel and BM_Reference)\n" : s;
}

}  // namespace kolsky::benchsum
