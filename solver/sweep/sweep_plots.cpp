#include "sweep/sweep_plots.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace kolsky::sweep {

namespace {

struct Stats {
  double mean = 0, sd = 0;
  std::size_t n = 0;
};

Stats stats(const std::vector<double>& v) {
  Stats s;
  s.n = v.size();
  for (double x : v) s.mean += x / static_cast<double>(s.n);
  if (s.n < 2) return s;
  double ss = 0;
  for (double x : v) ss += (x - s.mean) * (x - s.mean);
  s.sd = std::sqrt(ss / static_cast<double>(s.n - 1));
  return s;
}

// The x of each row and the axis label: the first key's numbers, or 1, 2, ... for its texts.
std::vector<double> x_values(const SweepTable& t, const std::string& key, std::string& xlabel) {
  const Column& c = t.column(key);
  xlabel = key;
  if (!c.text) return c.numbers;
  std::vector<std::string> seen;
  std::vector<double> x;
  for (const std::string& v : c.texts) {
    auto at = std::find(seen.begin(), seen.end(), v);
    if (at == seen.end()) at = seen.insert(seen.end(), v);
    x.push_back(static_cast<double>(at - seen.begin() + 1));
  }
  for (std::size_t k = 0; k < seen.size(); ++k) xlabel += (k ? ", " : " (") + std::to_string(k + 1) + ": " + seen[k];
  xlabel += ")";
  return x;
}

}  // namespace

std::vector<plot::Plot> sweep_figures(const SweepTable& t, const std::string& source) {
  // The keys that vary (a key given one value is the same change for every member).
  std::vector<nlohmann::json> axes;
  for (const auto& a : t.meta.at("axes"))
    if (a.at("values").size() > 1) axes.push_back(a);
  const std::string first = axes.empty() ? "seed" : axes[0].at("key").get<std::string>();
  if (axes.empty() && t.meta.value("seeds", 0) == 0) return {};
  const bool logx = !axes.empty() && axes[0].value("log_spaced", false);
  std::string xlabel;
  const std::vector<double> x = x_values(t, first, xlabel);
  // The group of each row: the other varied keys' values ("" with one key).
  std::vector<std::string> group(t.rows);
  for (std::size_t k = 1; k < axes.size(); ++k) {
    const Column& c = t.column(axes[k].at("key").get<std::string>());
    for (std::size_t r = 0; r < t.rows; ++r)
      group[r] += (group[r].empty() ? "" : " ") + c.name + "=" + (c.text ? c.texts[r] : value_text(c.numbers[r]));
  }
  const Column& status = t.column("status");
  std::vector<plot::Plot> out;
  for (const std::string& f : figure_columns(t)) {
    const Column& y = t.column(f);
    plot::Plot p;
    p.file = "sweep_" + f + ".png";
    p.title = f + " against " + first + " (" + source + ")";
    p.xlabel = xlabel;
    p.ylabel = f;
    p.logx = logx;
    // group -> x (ascending) -> the values of the members there
    std::map<std::string, std::map<double, std::vector<double>>> by_group;
    for (std::size_t r = 0; r < t.rows; ++r)
      if (status.texts[r] == "ok" && std::isfinite(y.numbers[r]) && std::isfinite(x[r]))
        by_group[group[r]][x[r]].push_back(y.numbers[r]);
    if (by_group.empty()) continue;
    for (const auto& [g, at] : by_group) {
      const std::string name = g.empty() ? "" : g + ": ";
      plot::PlotSeries members{name + "members", {}, {}, "points"};
      plot::PlotPoints mean{name + "mean +- sd", {}, {}, {}, {}};
      bool scatter = false;
      for (const auto& [xv, ys] : at) {
        for (double v : ys) {
          members.x.push_back(xv);
          members.y.push_back(v);
        }
        const Stats s = stats(ys);
        mean.x.push_back(xv);
        mean.y.push_back(s.mean);
        mean.yerr.push_back(s.sd);
        scatter = scatter || s.n > 1;
      }
      if (scatter) {
        p.series.push_back(std::move(members));
        p.reference_points.push_back(std::move(mean));
      } else {
        members.style = "linespoints";
        members.label = g.empty() ? f : g;
        p.series.push_back(std::move(members));
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace kolsky::sweep
