// Particle snapshots of a DEM specimen for ParaView: an HDF5 side file streamed during the run
// and an XDMF file describing it. Layout of the particle file:
//   /meta            attributes complete (1/0), count
//   /snapshots/<k>   k = 0, 1, ...: datasets position (n x 3, m), radius (n, m),
//                    velocity (n x 3, m/s), force (n x 3, N); attributes time (s), step
// The XDMF (<out>.xmf) is a temporal collection of Polyvertex grids whose DataItems point into
// the particle file by its name (both files lie side by side): radius as a Scalar attribute,
// velocity and force as Vector attributes. Both are written under temporary names and renamed
// by finish(); a run that blew up finishes with complete = 0 and keeps what it has.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "dem/particles.hpp"
#include "io/h5_util.hpp"

namespace kolsky::io {

/// ("<dir>/<stem>.particles.h5", "<dir>/<stem>.xmf") for a run output "<dir>/<stem>.h5".
std::pair<std::string, std::string> snapshot_paths(const std::string& run_output);

struct SnapshotInfo {
  long step = 0;
  double time = 0;
  std::size_t count = 0;  ///< particles
};

/// The XDMF 3 document for `snaps`, stored as /snapshots/<k> of `h5_name` (a path relative to
/// the XDMF file).
std::string xdmf_text(const std::string& h5_name, const std::vector<SnapshotInfo>& snaps);

class SnapshotWriter {
 public:
  /// Creates the particle file under a temporary name. Throws std::runtime_error naming it.
  SnapshotWriter(std::string h5_path, std::string xmf_path);
  ~SnapshotWriter();  ///< unfinished (an exception unwound the run): the temporary is removed
  SnapshotWriter(const SnapshotWriter&) = delete;
  SnapshotWriter& operator=(const SnapshotWriter&) = delete;

  /// Appends /snapshots/<count()> with the particles' state at time t (s) of step `step`.
  void add(long step, double t, const dem::Particles& p);
  /// Writes /meta/complete, closes, renames the particle file into place, then writes the XDMF.
  void finish(bool complete);
  std::size_t count() const { return snaps_.size(); }

 private:
  std::string h5_path_, xmf_path_, tmp_;
  h5::Handle file_, group_;
  std::vector<SnapshotInfo> snaps_;
  bool finished_ = false;
};

}  // namespace kolsky::io
