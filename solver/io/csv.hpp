// Numeric CSV tables: digitized reference curves (data/digitized/), pulse inputs, exported probes.
// Format: comma separated (a row without commas may separate its cells by blanks), cells
// whitespace-trimmed, lines starting with '#' and blank lines
// ignored, an optional header row (detected: the first row with any non-numeric cell), every
// other cell a number (nan/inf accepted). No quoting: names and values must not contain commas.
#pragma once
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace kolsky::io {

/// Column-major numeric table. header is empty for a headerless file; otherwise it has one name
/// per column. All columns have the same length.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> columns;
  std::vector<size_t> lines;  ///< 1-based file line of each data row (for error messages)
  std::vector<std::string> comments;  ///< the '#' lines, without the '#' and trimmed, in order

  /// Number of data rows (0 for a table without columns).
  size_t rows() const;
  /// The column called `name`; throws std::out_of_range naming it and the available columns.
  const std::vector<double>& column(const std::string& name) const;
};

/// Parses path. Throws kolsky::InputError(path, "line N", rule) for a missing file ("cannot
/// open"), a file without header or data, a ragged row, a non-numeric data cell, or an empty or
/// duplicate column name.
CsvTable read_csv(const std::string& path);
/// The same rules for a table read from `in` (the fuzz targets parse from memory); `path`
/// names it in errors.
CsvTable parse_csv(std::istream& in, const std::string& path);

/// Writes t atomically: each line of `comment` as "# line", then the header (if any), then the
/// rows with %.10g. Throws std::invalid_argument naming path if the header size or the column
/// lengths disagree, or a name contains a comma or line break; std::runtime_error on I/O failure.
void write_csv(const std::string& path, const CsvTable& t, const std::string& comment = "");

}  // namespace kolsky::io
