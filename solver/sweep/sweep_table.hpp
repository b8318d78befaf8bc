// The table of a sweep: one row per member, in member order, with the varied keys' values, the
// seed, the summary figures of its run (shpb/summary.hpp), its step count, run time, status and
// error, and its content key (the name of its cache file). Written as CSV (RFC 4180: a text cell
// holding a comma, quote or line break is quoted) and as HDF5 (/table/<column>: doubles or
// UTF-8 strings, in the order of /table's "columns" attribute, a JSON list of {name, text};
// /meta's meta_json: the scene, the keys, the binary), each through a temporary name renamed
// when complete.
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ensemble/ensemble.hpp"
#include "sweep/sweep_plan.hpp"

namespace kolsky::sweep {

struct Column {
  std::string name;
  bool text = false;              ///< strings (texts) or numbers (numbers; NaN where missing)
  std::vector<double> numbers;
  std::vector<std::string> texts;
};

struct SweepTable {
  std::vector<Column> columns;
  std::size_t rows = 0;
  nlohmann::json meta;            ///< scene file, keys and values, seeds, binary version

  /// The column called `name`; throws std::out_of_range naming it.
  const Column& column(const std::string& name) const;
};

/// Columns: member (1-based), each axis' key (numbers when every value is one), seed (with
/// --seeds), every summary figure any member has (in the order first met), steps, run_s,
/// status ("ok" / "failed"), failure_kind, error, key. `results` in point order.
SweepTable make_table(const SweepPlan& plan, const std::vector<SweepPoint>& points,
                      const std::vector<ensemble::MemberResult>& results);

/// The table as CSV text: a header row, then one line per row; numbers shortest round-trip,
/// "nan" where missing.
std::string csv_text(const SweepTable& t);

/// CSV and HDF5 written atomically; std::runtime_error naming the path on failure.
void write_table_csv(const std::string& path, const SweepTable& t);
void write_table_hdf5(const std::string& path, const SweepTable& t);

/// Reads write_table_hdf5's /table back (the tests compare it with the CSV).
SweepTable read_table_hdf5(const std::string& path);

/// The columns that hold the members' summary figures (for the figures), in table order.
std::vector<std::string> figure_columns(const SweepTable& t);

}  // namespace kolsky::sweep
