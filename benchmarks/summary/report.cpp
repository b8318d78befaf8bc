// The summary: three figures and reports/benchmarks/README.md (see report.hpp).
#include "summary/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "summary/plot.hpp"

namespace kolsky::benchsum {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

namespace {
std::string mega(std::optional<double> v) { return v ? fmt("%.2f", *v / 1e6) : ""; }
std::string ratio_text(const std::optional<Ratio>& r) {
  return r ? fmt("%.4g", r->ratio) + " (v" + std::to_string(r->version) + ")" : "no reference";
}
std::string short_commit(const ResultFile& f) {
  return (f.commit.empty() ? std::string("?") : f.commit.substr(0, 7)) + (f.kind == "bench-check" ? "*" : "");
}
std::string image(const std::string& file, const RenderResult& r) {
  return r.ok ? "![" + file + "](" + file + ")\n\n" : "(" + file + " " + r.message + ")\n\n";
}

const Tracked& find_tracked(const std::string& id) {
  for (const Tracked& t : tracked())
    if (t.id == id) return t;
  throw std::logic_error("no tracked figure " + id);
}

/// One y2 series of ratios per reference version (ratios of different versions are not
/// comparable, so they are never joined by a line).
void add_ratio_series(Figure& fig, const std::string& what, const std::vector<std::optional<Ratio>>& r) {
  std::set<int> versions;
  for (const auto& v : r)
    if (v) versions.insert(v->version);
  for (int ver : versions) {
    Series s{what + " / reference v" + std::to_string(ver) + " (right axis)", {}, {}, "open", true};
    for (std::size_t i = 0; i < r.size(); ++i)
      if (r[i] && r[i]->version == ver) {
        s.x.push_back(static_cast<double>(i));
        s.y.push_back(r[i]->ratio);
      }
    fig.series.push_back(s);
  }
}

// The batch law's instruction-set variants on the whole step, one row per bench_dem file that
// ran BM_DemKernelVariant (a variant the CPU lacked was skipped and has no entry).
std::string variant_table(const std::vector<ResultFile>& files) {
  static const char* const ids[] = {"dem_portable", "dem_avx2", "dem_avx512"};
  std::string rows;
  for (const ResultFile& f : files) {
    if (f.bench != "bench_dem") continue;
    std::string cells;
    bool any = false;
    for (const char* id : ids) {
      const Tracked& t = find_tracked(id);
      const auto v = value(f, t.kernel, t.counter);
      any = any || v.has_value();
      cells += " | " + (v ? mega(v) + " (" + ratio_text(ratio(f, t)) + ")" : std::string("not run"));
    }
    if (any) rows += "| `" + f.commit + "` | " + short_date(f.time) + cells + " |\n";
  }
  if (rows.empty()) return "";
  return "**The batch law's instruction-set variants** (`BM_DemKernelVariant`, 1 thread, M particle-steps/s and "
         "the ratio to `BM_Reference/1` per CPU second; docs/dem.md, \"The roofline point\"):\n\n"
         "| run | date (UTC) | portable (SSE2) | AVX2 | AVX-512 |\n|---|---|---|---|---|\n" +
         rows + "\n";
}

// (a) BM_DemCompaction over commits, LAMMPS runs as their own x positions in date order.
std::string dem_section(const std::vector<ResultFile>& files, const std::string& out, const std::string& gp,
                        std::vector<std::string>& written) {
  std::vector<const ResultFile*> rows;
  for (const ResultFile& f : files)
    if ((f.bench == "bench_dem" && (value(f, "BM_DemCompaction/1", "particle_steps_per_s") ||
                                    value(f, "BM_DemCompaction/2", "particle_steps_per_s"))) ||
        (f.bench == "lammps" && f.lammps_rate))
      rows.push_back(&f);
  Figure fig;
  fig.file = "dem_compaction.png";
  fig.title = "DEM BM_DemCompaction (pack_35k, 200 steps per iteration) over commits";
  fig.xlabel = "commit, in date order (* = short bench-check run)";
  fig.ylabel = "M particle-steps/s";
  fig.y2label = "rate / BM_Reference rate (same process)";
  Series one{"kolsky 1 thread", {}, {}, "linespoints", false}, two{"kolsky 2 threads", {}, {}, "linespoints", false};
  Series lmp{"LAMMPS gran/hertz/history, 1 core", {}, {}, "points", false};
  Series busy{"kolsky 2 threads, second core busy (not comparable)", {}, {}, "points", false};
  std::vector<std::optional<Ratio>> r1, r2;
  std::string table =
      "| run | date (UTC) | packing | 1 thread (M/s) | 1 thread / reference (per CPU s) | 2 threads (M/s) | "
      "2 threads / reference (per wall s) | LAMMPS gran/hertz/history, 1 core (M/s) |\n|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ResultFile& f = *rows[i];
    const double x = static_cast<double>(i);
    if (f.bench == "lammps") {
      fig.xtics.push_back("LAMMPS " + short_date(f.time).substr(11));
      lmp.x.push_back(x);
      lmp.y.push_back(*f.lammps_rate / 1e6);
      r1.emplace_back();
      r2.emplace_back();
      table += "| LAMMPS `" + f.name + "` (" + std::to_string(f.lammps_runs) + " runs, median) | " +
               short_date(f.time) + " | pack_35k | | | | | " + mega(f.lammps_rate) + " |\n";
      continue;
    }
    fig.xtics.push_back(short_commit(f));
    const auto v1 = value(f, "BM_DemCompaction/1", "particle_steps_per_s");
    const auto v2 = value(f, "BM_DemCompaction/2", "particle_steps_per_s");
    if (v1) {
      one.x.push_back(x);
      one.y.push_back(*v1 / 1e6);
    }
    r1.push_back(ratio(f, find_tracked("dem_1t")));
    // A 2-thread run that lacked the second core (known only when it has the reference) is
    // drawn apart, its ratio marked in the table and left out of the figure.
    const auto r2_all = ratio(f, find_tracked("dem_2t"));
    const bool r2_ok = usable(f, find_tracked("dem_2t"));
    if (v2) {
      Series& s2 = r2_all && !r2_ok ? busy : two;
      s2.x.push_back(x);
      s2.y.push_back(*v2 / 1e6);
    }
    r2.push_back(r2_ok ? r2_all : std::nullopt);
    const std::string r2_text =
        ratio_text(r2_all) + (r2_all && !r2_ok ? "; second core busy (BM_Reference 2 / 1 threads " +
                                                      fmt("%.2f", two_core_factor(f).value_or(0)) + ")"
                                               : "");
    std::string packing;
    for (const Entry& e : f.entries)
      if (e.key.rfind("BM_DemCompaction/", 0) == 0 && !e.label.empty()) packing = e.label;
    table += "| `" + f.commit + "`" + (f.kind == "bench-check" ? " (bench-check)" : "") + " | " + short_date(f.time) +
             " | " + (packing.empty() ? "not recorded" : packing) + " | " + mega(v1) + " | " + ratio_text(r1.back()) +
             " | " + mega(v2) + " | " + r2_text + " | |\n";
  }
  fig.series = {one, two, lmp, busy};
  add_ratio_series(fig, "1 thread", r1);
  add_ratio_series(fig, "2 threads", r2);
  const RenderResult rr = render(fig, out, gp);
  if (rr.ok) written.push_back(out + "/" + fig.file);
  return "## (a) DEM: `BM_DemCompaction` over commits\n\n" + image(fig.file, rr) +
         "Mean over the repetitions of each file (`_mean` aggregate); the rates are per wall second. Absolute rates of different rows come from "
         "different hours of a VM whose speed drifts by 15-25 %: compare them only through the ratio columns, "
         "which older files (before the reference workload) do not have. Ratios are comparable only within one "
         "reference version (vN); a 2-thread ratio counts only when the run had both cores (`BM_Reference` on 2 "
         "threads at least 1.9 x its 1-thread rate; otherwise it is marked and left out of the figure). LAMMPS rows are the runs of `benchmarks/lammps/run.sh` (median "
         "particle-steps/s of `gran/hertz/history` on one rank); kolsky / LAMMPS ratios from alternated rounds "
         "are in docs/dem.md, \"Performance\".\n\n" +
         table + "\n" + variant_table(files);
}

// (b) FE element updates over commits.
std::string fe_section(const std::vector<ResultFile>& files, const std::string& out, const std::string& gp,
                       std::vector<std::string>& written) {
  const std::vector<std::pair<std::string, std::string>> kernels = {
      {"BM_FeSpecimenStep/10/20", "specimen 10 x 20 (Chapter 2 mesh)"},
      {"BM_FeSpecimenStep/20/40", "specimen 20 x 40"},
      {"BM_MeshedBarsStep", "meshed bars + specimen"}};
  Figure fig;
  fig.file = "fe_elem_updates.png";
  fig.title = "FE element updates per second over commits (1 thread)";
  fig.xlabel = "commit, in date order (* = short bench-check run)";
  fig.ylabel = "M element updates/s";
  fig.y2label = "rate / BM_Reference rate (same process)";
  std::vector<Series> series;
  for (const auto& [key, name] : kernels) series.push_back(Series{name, {}, {}, "linespoints", false});
  std::vector<std::optional<Ratio>> r;
  std::string table = "| commit | date (UTC) |";
  for (const auto& k : kernels) table += " " + k.second + " (M/s) |";
  table += " 10 x 20 / reference (per CPU s) |\n|---|---|---|---|---|---|\n";
  for (const ResultFile& f : files) {
    if (f.bench != "bench_fe") continue;
    const double x = static_cast<double>(fig.xtics.size());
    fig.xtics.push_back(short_commit(f));
    table += "| `" + f.commit + "`" + (f.kind == "bench-check" ? " (bench-check)" : "") + " | " + short_date(f.time) + " |";
    for (std::size_t k = 0; k < kernels.size(); ++k) {
      const auto v = value(f, kernels[k].first, "elem_updates_per_s");
      if (v) {
        series[k].x.push_back(x);
        series[k].y.push_back(*v / 1e6);
      }
      table += " " + mega(v) + " |";
    }
    r.push_back(ratio(f, find_tracked("fe")));
    table += " " + ratio_text(r.back()) + " |\n";
  }
  fig.series = series;
  add_ratio_series(fig, "10 x 20", r);
  const RenderResult rr = render(fig, out, gp);
  if (rr.ok) written.push_back(out + "/" + fig.file);
  return "## (b) FE: element updates per second over commits\n\n" + image(fig.file, rr) +
         "`bench_fe` (`elem_updates_per_s`, mean aggregate, per CPU second as Google Benchmark counts it without "
         "UseRealTime); the tracked figure is the 10 x 20 specimen's rate over `BM_Reference/1`'s of the same "
         "process, both per CPU second.\n\n" +
         table + "\n";
}

// (c) Wall time per simulated microsecond against the upscaling factor N, log-log, fitted.
std::string upscale_section(const std::vector<ResultFile>& files, const std::string& out, const std::string& gp,
                            std::vector<std::string>& written) {
  const ResultFile* newest = nullptr;
  for (const ResultFile& f : files)
    if (f.bench == "bench_dem" && !upscale_series(f).empty()) newest = &f;  // files are in date order
  std::string s = "## (c) DEM: cost against the upscaling factor N (`BM_DemUpscale`)\n\n";
  if (!newest) return s + "No bench_dem file has `BM_DemUpscale` results.\n\n";
  const std::vector<UpscalePoint> pts = upscale_series(*newest);
  std::vector<double> n, y;
  for (const UpscalePoint& p : pts) {
    n.push_back(p.n);
    y.push_back(p.s_per_sim_us);
  }
  const auto fit = fit_power_law(n, y);
  const std::string exponent = fit ? fmt("%.2f", fit->exponent) : "n/a";
  Figure fig;
  fig.file = "dem_upscaling.png";
  fig.title = "DEM upscaling, " + newest->commit.substr(0, 7) + " (" + short_date(newest->time) +
              "): wall s per simulated us ~ N^" + exponent;
  fig.xlabel = "upscaling factor N";
  fig.ylabel = "wall seconds per simulated microsecond";
  fig.logx = fig.logy = true;
  fig.key = "top right";
  fig.series.push_back(Series{"measured (BM_DemUpscale, 1 thread)", n, y, "linespoints", false});
  // The measured N as tics, on a range just around them (gnuplot's log axis would run to 10).
  fig.extra = "set xrange [" + fmt("%g", 0.9 * n.front()) + ":" + fmt("%g", 1.1 * n.back()) + "]\nset xtics (";
  for (std::size_t i = 0; i < n.size(); ++i) fig.extra += (i ? ", " : "") + fmt("%g", n[i]);
  fig.extra += ")\n";
  if (fit) {
    Series line{"least squares: " + fmt("%.4g", fit->prefactor) + " N^" + exponent + " (" +
                    std::to_string(fit->points) + " points)", {}, {}, "dashed", false};
    for (double v : n) {
      line.x.push_back(v);
      line.y.push_back(fit->prefactor * std::pow(v, fit->exponent));
    }
    fig.series.push_back(line);
  }
  const RenderResult rr = render(fig, out, gp);
  if (rr.ok) written.push_back(out + "/" + fig.file);
  const auto ref = value(*newest, "BM_Reference/1", kReferenceCounter);  // both per wall second
  s += image(fig.file, rr) + "From `" + newest->name + "`, the newest file with `BM_DemUpscale` (the Song "
       "specimen's jammed packing of the curve upscaled by N). Fitted exponent " + exponent +
       " (N^-3 grains times N^-1 steps give -4 at a fixed rate; the rate also rises as the specimen "
       "shrinks into the caches).\n\n| N | grains | M particle-steps/s | rate / reference | s per simulated us | "
       "fit | measured / fit |\n|---|---|---|---|---|---|---|\n";
  for (const UpscalePoint& p : pts) {
    const double f = fit ? fit->prefactor * std::pow(p.n, fit->exponent) : 0;
    s += "| " + fmt("%g", p.n) + " | " + fmt("%.0f", p.grains) + " | " + fmt("%.2f", p.rate / 1e6) + " | " +
         (ref ? fmt("%.4g", p.rate / *ref) : "no reference") + " | " + fmt("%.4g", p.s_per_sim_us) + " | " +
         (fit ? fmt("%.4g", f) : "") + " | " + (fit ? fmt("%.3f", p.s_per_sim_us / f) : "") + " |\n";
  }
  return s + "\n";
}

}  // namespace

// (d) The Chapter 5 set as an ensemble: the list-scheduling model of its measured members
// (issue 33), as study_ch5_schedule --json writes it (scripts/run-benchmarks.sh).
std::string ensemble_section(const std::vector<ResultFile>& files) {
  std::string s = "## (d) Chapter 5 as an ensemble: the list-scheduling model (`BM_Ch5SetModel`)\n\n";
  std::string history;
  const ResultFile* newest = nullptr;
  for (const ResultFile& f : files) {
    if (f.bench != "bench_ch5_model") continue;
    newest = &f;  // files are in date order
    const auto at16 = value(f, "BM_Ch5SetModel/16", "makespan_s");
    const auto crit = value(f, "BM_Ch5SetModel/16", "critical_path_s");
    const auto one = value(f, "BM_Ch5SetModel/1", "makespan_s");
    history += "| `" + f.commit + "` | " + short_date(f.time) + " | " + (one ? fmt("%.1f", *one / 60) : "") + " | " +
               (at16 ? fmt("%.1f", *at16 / 60) : "") + " | " + (crit ? fmt("%.1f", *crit / 60) : "") + " |\n";
  }
  if (!newest) return s + "No `bench_ch5_model` file (run `make bench` after a full Chapter 5 run).\n\n";
  s += "Each member's measured run time (`reproductions/chapter5/members_full_measured.json`, from the newest full "
       "run), scheduled phase by phase, longest first, on K ranks (`reproductions/chapter5/set.hpp`): a model, "
       "not a timing. The critical path (the phases' longest members summed) is the floor no rank count "
       "lowers.\n\nNewest, `" + newest->name + "`:\n\n| ranks | makespan (min) | critical path (min) | idle |\n|---|---|---|---|\n";
  for (const Entry& e : newest->entries) {
    if (e.key.rfind("BM_Ch5SetModel/", 0) != 0) continue;
    auto c = [&](const char* k) { return e.counters.count(k) ? e.counters.at(k) : NAN; };
    s += "| " + e.key.substr(std::string("BM_Ch5SetModel/").size()) + " | " + fmt("%.1f", c("makespan_s") / 60) + " | " +
         fmt("%.1f", c("critical_path_s") / 60) + " | " + fmt("%.0f %%", 100 * c("idle_fraction")) + " |\n";
  }
  return s + "\nOver commits:\n\n| commit | date (UTC) | 1 rank (min) | 16 ranks (min) | critical path (min) |\n"
             "|---|---|---|---|---|\n" + history + "\n";
}

std::vector<std::string> write_summary(const std::vector<ResultFile>& files, const std::vector<std::string>& skipped,
                                       const std::string& out, const std::string& gnuplot, std::ostream& log) {
  std::filesystem::create_directories(out);
  std::vector<std::string> written;
  std::string md =
      "# Benchmark tracking\n\nGenerated by `make bench-summary` (`benchmarks/summary/`) from " +
      std::to_string(files.size()) + " files of `benchmarks/results/`; do not edit, rerun it.\n\n"
      "**Read the ratios, not the rates.** The development VM's speed drifts by 15-25 % between minutes, so "
      "the tracked speed figure is a kolsky rate divided by the rate of `BM_Reference` (a frozen "
      "gather-scatter spring workload, `benchmarks/reference_workload.hpp`) measured in the same process. "
      "1-thread ratios are of rates per second of CPU time (a wall-time rate times real_time / cpu_time), so "
      "that time spent waiting for a core while another process runs drops out of both; 2-thread ratios are "
      "of wall-time rates. `make bench-check` compares a short run's ratios with the newest tracked ones "
      "(margins and their measurement: `scripts/bench-check.sh`).\n\n";
  md += dem_section(files, out, gnuplot, written);
  md += fe_section(files, out, gnuplot, written);
  md += upscale_section(files, out, gnuplot, written);
  md += ensemble_section(files);
  md += "## Files read\n\n";
  for (const ResultFile& f : files) {
    const bool used = f.bench == "bench_dem" || f.bench == "bench_fe" || f.bench == "lammps" || f.bench == "bench_ch5_model";
    md += "- `" + f.name + "` (" + short_date(f.time) + ")" + (used ? "" : ": no figure of this summary uses " + f.bench) + "\n";
  }
  for (const std::string& s : skipped) md += "- skipped " + s + "\n";
  const std::string readme = out + "/README.md";
  write_file_atomic(readme, md);
  written.push_back(readme);
  for (const std::string& w : written) log << "bench-summary: wrote " << w << "\n";
  for (const std::string& s : skipped) log << "bench-summary: skipped " << s << "\n";
  return written;
}

}  // namespace kolsky::benchsum
