// The ensemble's MPI executor (plain MPI C API; built when CMake finds MPI). Rank 0 keeps the
// schedule: it hands each rank that reports ready the next member (longest expected first),
// runs members itself on a second thread that makes no MPI calls (MPI_THREAD_FUNNELED), stores
// finished results in the cache, and broadcasts all of them at the end. A member's failure is
// a result like any other: no MPI_Abort, the other members go on.
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <mpi.h>
#include <mutex>
#include <optional>
#include <thread>

#include "ensemble/ensemble_wire.hpp"

namespace kolsky::ensemble {

namespace {

constexpr int kTagReady = 1, kTagAssign = 2;

// Started by a launcher (mpirun / srun)? A program started alone stays serial: no MPI_Init.
bool under_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

bool mpi_running() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

std::string receive_text(int source, int tag, MPI_Status* status) {
  MPI_Probe(source, tag, MPI_COMM_WORLD, status);
  int length = 0;
  MPI_Get_count(status, MPI_CHAR, &length);
  std::string text(static_cast<std::size_t>(length), '\0');
  MPI_Recv(text.data(), length, MPI_CHAR, status->MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

// Rank 0's own member runner: one member at a time on a thread of its own.
struct LocalRunner {
  std::mutex mutex;
  std::condition_variable wake;
  long job = -1;
  bool stop = false;
  std::optional<std::pair<std::size_t, MemberResult>> finished;
  bool busy() const { return job >= 0 || finished.has_value(); }
};

void worker_loop(const std::vector<EnsembleMember>& members, int rank) {
  std::string report = "{}";
  for (;;) {
    MPI_Send(report.data(), static_cast<int>(report.size()), MPI_CHAR, 0, kTagReady, MPI_COMM_WORLD);
    long index = -1;
    MPI_Recv(&index, 1, MPI_LONG, 0, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0) return;
    const MemberResult r = run_member(members[static_cast<std::size_t>(index)], "", rank);
    report = nlohmann::json{{"index", index}, {"result", to_wire(r)}}.dump();
  }
}

void schedule_on_root(const std::vector<EnsembleMember>& members, const EnsembleOptions& o,
                      const std::vector<std::size_t>& order, std::vector<MemberResult>& out, int size) {
  std::size_t done = 0;
  auto finish = [&](std::size_t m, MemberResult r) {
    if (r.ok && !r.cached) cache_store(o.cache_dir, members[m].key, r.value);
    out[m] = std::move(r);
    ++done;
    if (o.on_done) o.on_done(out[m], done, members.size());
  };
  // Cached members are answered here and never sent.
  std::vector<std::size_t> queue;
  for (std::size_t m : order) {
    if (auto hit = cached_result(members[m], o.cache_dir, 0)) {
      finish(m, std::move(*hit));
    } else {
      queue.push_back(m);
    }
  }
  std::size_t next = 0;
  LocalRunner local;
  std::thread runner([&] {
    std::unique_lock<std::mutex> lock(local.mutex);
    for (;;) {
      local.wake.wait(lock, [&] { return local.stop || local.job >= 0; });
      if (local.job < 0) return;
      const auto m = static_cast<std::size_t>(local.job);
      lock.unlock();
      MemberResult r = run_member(members[m], "", 0);
      lock.lock();
      local.finished.emplace(m, std::move(r));
      local.job = -1;
    }
  });
  int remote_active = size - 1;
  while (done < members.size() || remote_active > 0) {
    bool idle = true;
    {
      std::unique_lock<std::mutex> lock(local.mutex);
      if (local.finished) {
        auto [m, r] = std::move(*local.finished);
        local.finished.reset();
        lock.unlock();
        finish(m, std::move(r));
        lock.lock();
        idle = false;
      }
      if (!local.busy() && next < queue.size()) {
        local.job = static_cast<long>(queue[next++]);
        local.wake.notify_one();
      }
    }
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagReady, MPI_COMM_WORLD, &flag, &status);
    if (flag) {
      const nlohmann::json report = nlohmann::json::parse(receive_text(status.MPI_SOURCE, kTagReady, &status));
      if (report.contains("index")) finish(report.at("index").get<std::size_t>(), from_wire(report.at("result")));
      const long assign = next < queue.size() ? static_cast<long>(queue[next++]) : -1;
      MPI_Send(&assign, 1, MPI_LONG, status.MPI_SOURCE, kTagAssign, MPI_COMM_WORLD);
      if (assign < 0) --remote_active;
      idle = false;
    }
    if (idle) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  {
    const std::lock_guard<std::mutex> lock(local.mutex);
    local.stop = true;
  }
  local.wake.notify_one();
  runner.join();
}

}  // namespace

bool built_with_mpi() { return true; }

RankLayout rank_layout() {
  RankLayout l;
  if (!mpi_running()) return l;
  MPI_Comm_rank(MPI_COMM_WORLD, &l.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &l.size);
  return l;
}

MpiSession::MpiSession(int* argc, char*** argv) {
  if (!under_launcher() || mpi_running()) return;
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
}

MpiSession::~MpiSession() {
  if (mpi_running()) MPI_Finalize();
}

std::vector<MemberResult> run_over_ranks(const std::vector<EnsembleMember>& members, const EnsembleOptions& o,
                                         const std::vector<std::size_t>& order) {
  const RankLayout l = rank_layout();
  std::vector<MemberResult> out(members.size());
  if (l.rank == 0) schedule_on_root(members, o, order, out, l.size);
  else worker_loop(members, l.rank);
  // Every rank returns every result, in member order.
  std::string all;
  if (l.rank == 0) {
    nlohmann::json a = nlohmann::json::array();
    for (const MemberResult& r : out) a.push_back(to_wire(r));
    all = a.dump();
  }
  long length = static_cast<long>(all.size());
  MPI_Bcast(&length, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  all.resize(static_cast<std::size_t>(length));
  MPI_Bcast(all.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD);
  if (l.rank != 0) {
    const nlohmann::json a = nlohmann::json::parse(all);
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = from_wire(a.at(k));
  }
  return out;
}

}  // namespace kolsky::ensemble
