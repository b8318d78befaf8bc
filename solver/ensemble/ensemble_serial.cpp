// The ensemble's stand-in for a build without MPI: one process, the members on threads.
#include <stdexcept>

#include "ensemble/ensemble.hpp"

namespace kolsky::ensemble {

bool built_with_mpi() { return false; }
RankLayout rank_layout() { return {}; }
MpiSession::MpiSession(int*, char***) {}
MpiSession::~MpiSession() = default;

std::vector<MemberResult> run_over_ranks(const std::vector<EnsembleMember>&, const EnsembleOptions&,
                                         const std::vector<std::size_t>&) {
  throw std::logic_error("run_over_ranks: this build has no MPI (rank_layout() is always one rank)");
}

}  // namespace kolsky::ensemble
