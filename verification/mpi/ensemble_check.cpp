// ensemble_check: the ensemble executor under mpirun (issue 33). Every rank builds the same
// members; the ensemble runs over the ranks; rank 0 then runs each member itself and checks
// that every rank's result is bitwise the serial one (JSON text of the values), that the
// failing member is recorded and did not stop the others, and, on a second pass with a cache,
// that nothing runs again. Exit 0 when all hold. Usage: ensemble_check CACHE_DIR
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "ensemble/ensemble.hpp"

using namespace kolsky::ensemble;

int main(int argc, char** argv) {
  MpiSession mpi(&argc, &argv);
  const RankLayout l = rank_layout();
  if (argc != 2) {
    std::fprintf(stderr, "usage: ensemble_check CACHE_DIR\n");
    return 2;
  }
  const std::string cache = argv[1];
  std::vector<EnsembleMember> members;
  for (int k = 0; k < 12; ++k) {
    EnsembleMember e;
    e.label = "member " + std::to_string(k);
    e.key = "check" + std::to_string(k);
    e.expected_cost = 1 + k % 4;
    e.run = [k] {
      if (k == 5) throw std::runtime_error("member 5 fails on purpose");
      double s = 0;
      for (int i = 1; i <= 200000 * (1 + k % 4); ++i) s += std::sin(1e-4 * i * (k + 1)) / i;
      return nlohmann::json{{"k", k}, {"s", s}};
    };
    members.push_back(std::move(e));
  }
  if (l.rank == 0) std::filesystem::remove_all(cache);
  EnsembleOptions o;
  o.threads = 2;  // used only when there is one rank
  o.cache_dir = cache;
  const std::vector<MemberResult> got = run_ensemble(members, o);
  int bad = 0, ranks_used = 0;
  std::vector<int> seen(static_cast<std::size_t>(l.size), 0);
  for (std::size_t k = 0; k < members.size(); ++k) {
    const bool should_fail = k == 5;
    std::string serial = "null";
    if (!should_fail) serial = members[k].run().dump();
    if (got[k].ok == should_fail || got[k].value.dump() != serial) {
      std::fprintf(stderr, "rank %d: member %zu differs: %s against %s (%s)\n", l.rank, k, got[k].value.dump().c_str(),
                   serial.c_str(), got[k].error.c_str());
      ++bad;
    }
    if (got[k].rank >= 0 && got[k].rank < l.size) seen[static_cast<std::size_t>(got[k].rank)] = 1;
  }
  for (int s : seen) ranks_used += s;
  if (ranks_used != l.size) {  // 12 members on fewer ranks: every rank must have run some
    std::fprintf(stderr, "rank %d: members ran on %d of %d ranks\n", l.rank, ranks_used, l.size);
    ++bad;
  }
  const std::vector<MemberResult> again = run_ensemble(members, o);
  for (std::size_t k = 0; k < members.size(); ++k)
    if (again[k].cached != (k != 5) || again[k].value.dump() != got[k].value.dump()) {
      std::fprintf(stderr, "rank %d: member %zu not taken from the cache on the second pass\n", l.rank, k);
      ++bad;
    }
  if (l.rank == 0)
    std::printf("ensemble_check: %d rank(s), members run on %d of them, %s\n", l.size, ranks_used,
                bad == 0 ? "every result bitwise the serial one" : "MISMATCH");
  return bad == 0 ? 0 : 1;
}
