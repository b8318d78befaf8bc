// See results.hpp.
#include "summary/results.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace kolsky::benchsum {
namespace {

bool is_hex(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isxdigit(c); });
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

// Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant's days_from_civil): no
// timegm(), whose use of the TZ environment would make the ordering depend on the machine.
long long days_from_civil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

// Google Benchmark's own fields of a record; every other number is a user counter.
const std::set<std::string>& fixed_fields() {
  static const std::set<std::string> f = {"family_index", "per_family_instance_index",
                                          "repetitions", "repetition_index", "threads",
                                          "iterations", "real_time", "cpu_time"};
  return f;
}

// benchmarks/lammps/run.sh: summary[] holds the median over the runs per style and rank count;
// the peer figure of the issue is gran/hertz/history on one rank.
void parse_lammps(const nlohmann::json& j, ResultFile& f) {
  if (j.contains("summary") && j["summary"].is_array())
    for (const auto& s : j["summary"])
      if (s.value("style", "") == "hertz_history" && s.value("ranks", 0) == 1 &&
          s.contains("median_particle_steps_per_s"))
        f.lammps_rate = s["median_particle_steps_per_s"].get<double>();
  if (j.contains("runs") && j["runs"].is_array())
    for (const auto& r : j["runs"])
      if (r.value("style", "") == "hertz_history" && r.value("ranks", 0) == 1) ++f.lammps_runs;
  if (!f.lammps_rate) throw std::runtime_error("no summary entry for hertz_history on 1 rank");
}

}  // namespace

std::string normalize_key(const std::string& run_name) {
  std::string out;
  for (const std::string& t : split(run_name, '/')) {
    if (t == "real_time" || t == "process_time" || t == "manual_time" ||
        t.rfind("iterations:", 0) == 0 || t.rfind("min_time:", 0) == 0 || t.rfind("repeats:", 0) == 0)
      continue;
    out += (out.empty() ? "" : "/") + t;
  }
  return out;
}

long long parse_iso_time(const std::string& s) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, sec = 0, used = 0;
  if (std::sscanf(s.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d%n", &y, &mo, &d, &h, &mi, &sec, &used) != 6 ||
      mo < 1 || mo > 12 || d < 1 || d > 31)
    throw std::invalid_argument("date '" + s + "' is not YYYY-MM-DDTHH:MM:SS[+HH:MM]");
  std::string zone = s.substr(static_cast<std::size_t>(used));
  if (!zone.empty() && zone[0] == '.') {  // fractional seconds: ignored
    std::size_t k = 1;
    while (k < zone.size() && std::isdigit(static_cast<unsigned char>(zone[k]))) ++k;
    zone = zone.substr(k);
  }
  long long offset = 0;
  if (!zone.empty() && zone != "Z") {
    int zh = 0, zm = 0;
    if ((zone[0] != '+' && zone[0] != '-') || std::sscanf(zone.c_str() + 1, "%2d:%2d", &zh, &zm) != 2)
      throw std::invalid_argument("date '" + s + "': zone '" + zone + "' is not +HH:MM");
    offset = (zone[0] == '-' ? -1 : 1) * (zh * 3600LL + zm * 60LL);
  }
  return days_from_civil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d)) * 86400 +
         h * 3600LL + mi * 60LL + sec - offset;
}

std::string short_date(long long t) {
  long long days = t / 86400, rem = t % 86400;
  if (rem < 0) {
    rem += 86400;
    --days;
  }
  // civil_from_days (H. Hinnant), the inverse of days_from_civil.
  const long long z = days + 719468;
  const long long era = (z >= 0 ? z : z - 146096) / 146097;
  const auto doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  const unsigned d = doy - (153 * mp + 2) / 5 + 1;
  const unsigned m = mp < 10 ? mp + 3 : mp - 9;
  const long long y = static_cast<long long>(yoe) + era * 400 + (m <= 2);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%04lld-%02u-%02u %02lld:%02lld", y, m, d, rem / 3600, rem % 3600 / 60);
  return buf;
}

std::pair<std::string, std::string> parse_file_name(const std::string& name) {
  std::string stem = name;
  if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, ".json") == 0) stem.resize(stem.size() - 5);
  if (stem == "lammps" || (stem.size() > 7 && stem.compare(stem.size() - 7, 7, "_lammps") == 0))
    return {"lammps", ""};
  const std::size_t b = stem.find("_bench_");
  const std::string bench = b == std::string::npos ? "" : stem.substr(b + 1);
  std::string commit;
  // The commit: the hex token of 7-40 digits after the date (the date, 8 decimal digits, and
  // an HHMM stamp are hex too, so the first token is skipped and 4-digit ones do not count).
  const std::vector<std::string> tokens = split(stem.substr(0, b), '_');
  for (std::size_t k = 1; k < tokens.size(); ++k)
    if (tokens[k].size() >= 7 && tokens[k].size() <= 40 && is_hex(tokens[k])) commit = tokens[k];
  return {bench, commit};
}

ResultFile parse_result(const nlohmann::json& j, const std::string& file_name) {
  ResultFile f;
  f.name = file_name;
  std::tie(f.bench, f.commit) = parse_file_name(file_name);
  if (!j.is_object() || !j.contains("context") || !j["context"].is_object())
    throw std::runtime_error("no \"context\" object");
  const nlohmann::json& ctx = j["context"];
  if (!ctx.contains("date") || !ctx["date"].is_string()) throw std::runtime_error("no context.date");
  f.date = ctx["date"].get<std::string>();
  f.time = parse_iso_time(f.date);
  f.kind = ctx.value("kind", "");
  if (f.bench == "lammps") {
    parse_lammps(j, f);
    return f;
  }
  if (f.bench.empty()) throw std::runtime_error("name is neither <date>_<commit>_bench_*.json nor *_lammps.json");
  if (!j.contains("benchmarks") || !j["benchmarks"].is_array()) throw std::runtime_error("no \"benchmarks\" array");
  for (const auto& b : j["benchmarks"]) {
    Entry e;
    if (b.value("error_occurred", false)) continue;  // a skipped run has no valid counters
    e.aggregate = b.value("run_type", "") == "aggregate" ? b.value("aggregate_name", "") : "";
    std::string run = b.value("run_name", "");
    if (run.empty()) {  // old files: the name carries the aggregate suffix
      run = b.value("name", "");
      if (!e.aggregate.empty() && run.size() > e.aggregate.size() + 1 &&
          run.compare(run.size() - e.aggregate.size() - 1, std::string::npos, "_" + e.aggregate) == 0)
        run.resize(run.size() - e.aggregate.size() - 1);
    }
    e.key = normalize_key(run);
    for (const std::string& t : split(run, '/')) e.real_time = e.real_time || t == "real_time";
    e.real = b.value("real_time", 0.0);
    e.cpu = b.value("cpu_time", 0.0);
    e.label = b.value("label", "");
    for (const auto& [k, v] : b.items())
      if (v.is_number() && !fixed_fields().count(k)) e.counters[k] = v.get<double>();
    f.entries.push_back(std::move(e));
  }
  return f;
}

ResultFile read_result_file(const std::string& path) {
  try {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open");
    nlohmann::json j;
    try {
      in >> j;
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(std::string("not JSON: ") + e.what());
    }
    return parse_result(j, std::filesystem::path(path).filename().string());
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

std::vector<ResultFile> read_results_dir(const std::string& dir, std::vector<std::string>& skipped) {
  std::vector<std::string> paths;
  for (const auto& de : std::filesystem::directory_iterator(dir))
    if (de.is_regular_file() && de.path().extension() == ".json") paths.push_back(de.path().string());
  std::sort(paths.begin(), paths.end());
  std::vector<ResultFile> files;
  for (const std::string& p : paths) {
    try {
      files.push_back(read_result_file(p));
    } catch (const std::exception& e) {
      skipped.push_back(e.what());
    }
  }
  std::stable_sort(files.begin(), files.end(),
                   [](const ResultFile& a, const ResultFile& b) { return a.time < b.time; });
  return files;
}

namespace {

// The mean aggregate of `key`'s counter, else the mean over its single runs; per CPU second
// when `cpu` (entries without both times are then ignored).
std::optional<double> pick(const ResultFile& f, const std::string& key, const std::string& counter, bool cpu) {
  double sum = 0;
  int n = 0;
  for (const Entry& e : f.entries) {
    if (e.key != key) continue;
    const auto it = e.counters.find(counter);
    if (it == e.counters.end()) continue;
    if (cpu && e.real_time && !(e.real > 0 && e.cpu > 0)) continue;
    const double v = cpu && e.real_time ? it->second * e.real / e.cpu : it->second;
    if (e.aggregate == "mean") return v;
    if (e.aggregate.empty()) {
      sum += v;
      ++n;
    }
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

}  // namespace

std::optional<double> value(const ResultFile& f, const std::string& key, const std::string& counter) {
  return pick(f, key, counter, false);
}

std::optional<double> cpu_rate(const ResultFile& f, const std::string& key, const std::string& counter) {
  return pick(f, key, counter, true);
}

const std::vector<Tracked>& tracked() {
  static const std::vector<Tracked> t = {
      {"dem_1t", "bench_dem", "BM_DemCompaction/1", "particle_steps_per_s", "BM_Reference/1",
       "DEM BM_DemCompaction, 1 thread", false, true},
      {"dem_2t", "bench_dem", "BM_DemCompaction/2", "particle_steps_per_s", "BM_Reference/2",
       "DEM BM_DemCompaction, 2 threads", true, false},
      {"fe", "bench_fe", "BM_FeSpecimenStep/10/20", "elem_updates_per_s", "BM_Reference/1",
       "FE BM_FeSpecimenStep 10 x 20", false, true},
      // The batch law's instruction-set variants on the whole step (issue 34): each tracked
      // where the CPU of the run had it (a skipped variant has no entry, so no ratio).
      {"dem_portable", "bench_dem", "BM_DemKernelVariant/0", "particle_steps_per_s", "BM_Reference/1",
       "DEM BM_DemKernelVariant portable (SSE2), 1 thread", false, true},
      {"dem_avx2", "bench_dem", "BM_DemKernelVariant/1", "particle_steps_per_s", "BM_Reference/1",
       "DEM BM_DemKernelVariant AVX2, 1 thread", false, true},
      {"dem_avx512", "bench_dem", "BM_DemKernelVariant/2", "particle_steps_per_s", "BM_Reference/1",
       "DEM BM_DemKernelVariant AVX-512, 1 thread", false, true}};
  return t;
}

std::optional<Ratio> ratio(const ResultFile& f, const Tracked& t) {
  if (f.bench != t.bench) return std::nullopt;
  const auto k = t.cpu_time ? cpu_rate(f, t.kernel, t.counter) : value(f, t.kernel, t.counter);
  const auto r = t.cpu_time ? cpu_rate(f, t.reference, kReferenceCounter) : value(f, t.reference, kReferenceCounter);
  const auto v = value(f, t.reference, "reference_version");
  if (!k || !r || !v || *r <= 0) return std::nullopt;
  return Ratio{*k, *r, *k / *r, static_cast<int>(std::lround(*v))};
}

std::optional<double> two_core_factor(const ResultFile& f) {
  const auto one = value(f, "BM_Reference/1", kReferenceCounter), two = value(f, "BM_Reference/2", kReferenceCounter);
  if (!one || !two || *one <= 0) return std::nullopt;
  return *two / *one;
}

bool usable(const ResultFile& f, const Tracked& t) {
  if (!ratio(f, t)) return false;
  if (!t.two_cores) return true;
  const auto c = two_core_factor(f);
  return c && *c >= kMinTwoCoreFactor;
}

std::optional<PowerFit> fit_power_law(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> lx, ly;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
    if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i])) {
      lx.push_back(std::log(x[i]));
      ly.push_back(std::log(y[i]));
    }
  const double n = static_cast<double>(lx.size());
  if (lx.size() < 2) return std::nullopt;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < lx.size(); ++i) {
    mx += lx[i] / n;
    my += ly[i] / n;
  }
  double sxx = 0, sxy = 0;  // centred sums: no cancellation for clustered x
  for (std::size_t i = 0; i < lx.size(); ++i) {
    sxx += (lx[i] - mx) * (lx[i] - mx);
    sxy += (lx[i] - mx) * (ly[i] - my);
  }
  if (sxx <= 0) return std::nullopt;  // a single distinct x
  const double p = sxy / sxx;
  return PowerFit{p, std::exp(my - p * mx), static_cast<int>(lx.size())};
}

std::vector<UpscalePoint> upscale_series(const ResultFile& f) {
  std::set<std::string> keys;
  for (const Entry& e : f.entries)
    if (e.key.rfind("BM_DemUpscale/", 0) == 0) keys.insert(e.key);
  std::vector<UpscalePoint> out;
  for (const std::string& k : keys) {
    const auto s = value(f, k, "s_per_sim_us");
    if (!s) continue;
    UpscalePoint p;
    p.n = std::strtod(k.c_str() + std::string("BM_DemUpscale/").size(), nullptr) / 10.0;  // arg: 10 N
    if (!(p.n > 0)) continue;
    p.s_per_sim_us = *s;
    p.rate = value(f, k, "particle_steps_per_s").value_or(0.0);
    p.grains = value(f, k, "grains").value_or(0.0);
    out.push_back(p);
  }
  std::sort(out.begin(), out.end(), [](const UpscalePoint& a, const UpscalePoint& b) { return a.n < b.n; });
  return out;
}

}  // namespace kolsky::benchsum
