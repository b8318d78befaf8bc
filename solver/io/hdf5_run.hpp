// One simulation run as an HDF5 file: resolved metadata plus probe time series.
// Layout (docs/architecture.md, "Output"):
//   /meta                 string attributes scene, git_commit, build_type, kolsky_version, failure,
//                         meta_json (the whole meta object); integer attribute complete (1/0)
//   /probes/<name>/t      1-D double, attribute unit = "s"
//   /probes/<name>/value  1-D double, attribute unit = the series unit
// Probes are read back in the order they were written. Serial HDF5: not thread-safe, so call
// these from one thread at a time.
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace kolsky::io {

/// One probe: samples value(t). t in s, value in `unit` (SI unless the name says otherwise).
struct Series {
  std::string name, unit;
  std::vector<double> t, value;
};

/// Everything a run leaves behind that reproductions read.
/// meta is a JSON object; the keys "scene", "git_commit", "build_type", "kolsky_version",
/// "failure" and "complete" are mirrored into /meta attributes (missing ones get defaults:
/// git_commit/build_type from the build, failure "", complete 0).
struct RunRecord {
  nlohmann::json meta = nlohmann::json::object();
  std::vector<Series> probes;
};

/// Writes rec to path through a temporary sibling file, renamed into place only when complete.
/// Preconditions: meta is an object (or null); probe names are unique, non-empty, without '/',
/// and each probe has t.size() == value.size().
/// Throws std::runtime_error naming path on a violated precondition or any HDF5 failure; the
/// temporary file is removed and an existing file at path is left untouched.
void write_run_hdf5(const std::string& path, const RunRecord& rec);

/// Reads a file written by write_run_hdf5. meta is restored exactly from /meta/meta_json; for
/// files without it, meta is rebuilt from the individual /meta attributes.
/// Throws std::runtime_error naming path (and the probe, where relevant) on any failure.
RunRecord read_run_hdf5(const std::string& path);

}  // namespace kolsky::io
