// Checkpoint files of `kolsky run` (HDF5, written through a temporary name and renamed): the
// complete shpb::ShpbState, bitwise (doubles as IEEE binary64), plus a JSON meta object (the
// resolved scene, so a restart can refuse another scene). Layout (format_version 2):
//   /                attributes format = "kolsky-checkpoint", format_version, meta_json
//   /loop            attributes next_step, steps, dt, stable_dt, arrival_time, w_i, w_r, w_t,
//                    injected, force_front, force_back, schedule_* (time_loop::Schedule: the
//                    step as refined after breaks, its base step, tick and time; version 2);
//                    datasets prev (3), t (samples)
//   /probes/<k>      k = 0, 1, ... in run order: dataset value, attributes name, unit, description
//   /bars/incident, /bars/transmission   attribute kind (characteristic | sphere_chain), state
//   /specimen        attribute kind (column | dem), state; dem: particle arrays (n x 3 / n),
//                    contact histories keyed by (i, j) and (wall, particle), walls, faces
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "shpb/simulation.hpp"

namespace kolsky::io {

struct Checkpoint {
  nlohmann::json meta = nlohmann::json::object();
  shpb::ShpbState state;
};

/// Throws std::runtime_error naming path on any failure; the temporary file is removed and an
/// existing file at path (the previous checkpoint) is left untouched.
void write_checkpoint_hdf5(const std::string& path, const Checkpoint& c);
/// Throws kolsky::InputError(path, "", reason) when the file cannot be read or is not a
/// checkpoint of this format (bad input to a restart: exit code 2).
Checkpoint read_checkpoint_hdf5(const std::string& path);

}  // namespace kolsky::io
