// The tables a scene can reference: a tabulated pulse (time_s, stress_pa), a compaction
// loading curve (strain, stress_pa) and a strain-rate history (time_s, strain_rate), read with
// io::read_csv (format in io/csv.hpp), then held to their rules: exactly two finite columns,
// SI units, increasing where the physics needs it.
// Errors: InputError(csv_path, "line N", rule), or path "" for whole-file problems.
#pragma once
#include <string>
#include <vector>

#include "core/table.hpp"
#include "io/csv.hpp"

namespace kolsky::scene {

/// Two numeric columns, with the 1-based file line of each row for error messages.
struct CsvColumns {
  std::vector<double> x, y;
  std::vector<size_t> line;
  std::vector<std::string> header;  ///< the column names, empty without a header row
};

/// Reads a two-column table; x_name/y_name name the columns in error messages. The first
/// non-comment row is taken as a header if any of its fields is not a number.
CsvColumns read_two_column_csv(const std::string& path, const std::string& x_name,
                               const std::string& y_name);

/// The same rules for a table already read (the fuzz targets parse from memory); `path`
/// names it in errors. The load_* functions below are read_csv followed by these.
CsvColumns two_columns(const io::CsvTable& t, const std::string& path, const std::string& x_name,
                       const std::string& y_name);
Table1D pulse_table(const io::CsvTable& t, const std::string& path);
Table1D strain_rate_table(const io::CsvTable& t, const std::string& path);
Table1D loading_curve(const io::CsvTable& t, const std::string& path);

/// Pulse table (time_s, stress_pa): at least 2 rows, time strictly increasing.
Table1D load_pulse_table(const std::string& path);

/// Strain-rate history (time_s, strain_rate in 1/s; Sec. 5.2.1): at least 2 rows, time
/// strictly increasing from >= 0 (the run starts at t = 0). A header, if present, must name
/// the columns time_s, strain_rate: a pulse table (time_s, stress_pa) given by mistake would
/// otherwise drive the wall at "rates" of 1e8 /s.
Table1D load_strain_rate_table(const std::string& path);

/// Loading curve (strain, stress_pa), compression positive: first row (0, 0), both columns
/// strictly increasing. The table extrapolates linearly past its last strain, so a specimen
/// compacted beyond the measured range keeps stiffening instead of flowing at constant stress.
Table1D load_loading_curve(const std::string& path);

}  // namespace kolsky::scene
