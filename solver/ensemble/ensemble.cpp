#include "ensemble/ensemble.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <numeric>
#include <queue>
#include <thread>

#include "core/atomic_file.hpp"
#include "ensemble/ensemble_wire.hpp"

namespace kolsky::ensemble {

std::vector<std::size_t> schedule_order(const std::vector<EnsembleMember>& members) {
  std::vector<std::size_t> order(members.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return members[a].expected_cost > members[b].expected_cost;
  });
  return order;
}

std::optional<MemberResult> cached_result(const EnsembleMember& member, const std::string& cache_dir, int rank) {
  if (cache_dir.empty() || member.key.empty()) return std::nullopt;
  const std::string file = cache_dir + "/" + member.key + ".json";
  if (!std::filesystem::exists(file)) return std::nullopt;
  MemberResult r;
  r.label = member.label;
  r.key = member.key;
  r.rank = rank;
  std::ifstream in(file);
  r.value = nlohmann::json::parse(in);  // written by cache_store: complete, or not there at all
  r.ok = r.cached = true;
  return r;
}

void cache_store(const std::string& cache_dir, const std::string& key, const nlohmann::json& value) {
  if (cache_dir.empty() || key.empty()) return;
  std::filesystem::create_directories(cache_dir);
  write_file_atomic(cache_dir + "/" + key + ".json", value.dump() + "\n");  // never half a result
}

MemberResult run_member(const EnsembleMember& member, const std::string& cache_dir, int rank) {
  if (auto hit = cached_result(member, cache_dir, rank)) return std::move(*hit);
  MemberResult r;
  r.label = member.label;
  r.key = member.key;
  r.rank = rank;
  const auto start = std::chrono::steady_clock::now();
  try {
    r.value = member.run();
    r.ok = true;
  } catch (const std::exception& e) {
    r.error = e.what();
  } catch (...) {
    r.error = "unknown exception";
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (r.ok) cache_store(cache_dir, member.key, r.value);
  return r;
}

namespace {

// The members on `threads` threads of this process, each taking the next in `order`.
std::vector<MemberResult> run_on_threads(const std::vector<EnsembleMember>& members, const EnsembleOptions& o,
                                         const std::vector<std::size_t>& order) {
  std::vector<MemberResult> out(members.size());
  std::atomic<std::size_t> next{0};
  std::mutex done_mutex;
  std::size_t done = 0;
  auto worker = [&] {
    for (std::size_t k; (k = next.fetch_add(1)) < order.size();) {
      const std::size_t m = order[k];
      out[m] = run_member(members[m], o.cache_dir, 0);
      const std::lock_guard<std::mutex> lock(done_mutex);
      ++done;
      if (o.on_done) o.on_done(out[m], done, members.size());
    }
  };
  const int n = std::max(1, std::min<int>(o.threads, static_cast<int>(members.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return out;
}

}  // namespace

std::vector<MemberResult> run_ensemble(const std::vector<EnsembleMember>& members, const EnsembleOptions& options) {
  const std::vector<std::size_t> order = schedule_order(members);
  if (rank_layout().size > 1) return run_over_ranks(members, options, order);
  return run_on_threads(members, options, order);
}

ScheduleModel simulate_list_schedule(const std::vector<double>& costs, int workers) {
  ScheduleModel m;
  if (costs.empty() || workers < 1) return m;
  std::vector<double> sorted = costs;
  std::stable_sort(sorted.begin(), sorted.end(), std::greater<>());
  // Min-heap of the workers' finishing times: each member goes to the first free worker.
  std::priority_queue<double, std::vector<double>, std::greater<>> free_at;
  for (int w = 0; w < workers; ++w) free_at.push(0.0);
  for (double c : sorted) {
    const double t = free_at.top();
    free_at.pop();
    free_at.push(t + c);
    m.makespan = std::max(m.makespan, t + c);
  }
  m.critical_path = sorted.front();
  const double total = std::accumulate(sorted.begin(), sorted.end(), 0.0);
  // Clamped: on one worker the makespan and the total sum the same costs in another order.
  m.idle_fraction = m.makespan > 0 ? std::max(0.0, 1 - total / (workers * m.makespan)) : 0;
  return m;
}

}  // namespace kolsky::ensemble
