#include "scene/csv_load.hpp"

#include <cmath>
#include <cstdio>

#include "core/errors.hpp"
#include "io/csv.hpp"

namespace kolsky::scene {

namespace {

std::string show(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string at_line(size_t line) { return "line " + std::to_string(line); }

}  // namespace

CsvColumns read_two_column_csv(const std::string& path, const std::string& x_name,
                               const std::string& y_name) {
  return two_columns(io::read_csv(path), path, x_name, y_name);  // format, header, ragged rows
}

CsvColumns two_columns(const io::CsvTable& t, const std::string& path, const std::string& x_name,
                       const std::string& y_name) {
  if (t.columns.size() != 2)
    throw InputError(path, t.lines.empty() ? "" : at_line(t.lines.front()),
                     "expected 2 columns (" + x_name + ", " + y_name + "), found " +
                         std::to_string(t.columns.size()));
  for (size_t r = 0; r < t.rows(); ++r)
    for (int k = 0; k < 2; ++k)
      if (!std::isfinite(t.columns[k][r]))
        throw InputError(path, at_line(t.lines[r]),
                         "'" + show(t.columns[k][r]) + "' is not a finite number (column " +
                             (k == 0 ? x_name : y_name) + ")");
  if (t.rows() < 2)
    throw InputError(path, "",
                     "needs at least 2 data rows (" + x_name + ", " + y_name + "), found " +
                         std::to_string(t.rows()));
  return CsvColumns{t.columns[0], t.columns[1], t.lines, t.header};
}

namespace {

void require_increasing(const std::string& path, const CsvColumns& c,
                        const std::vector<double>& col, const std::string& name) {
  for (size_t i = 1; i < col.size(); ++i)
    if (!(col[i] > col[i - 1]))
      throw InputError(path, at_line(c.line[i]),
                       name + " must be strictly increasing: " + show(col[i]) + " follows " +
                           show(col[i - 1]) + " (" + at_line(c.line[i - 1]) + ")");
}

}  // namespace

Table1D load_pulse_table(const std::string& path) {
  return pulse_table(io::read_csv(path), path);
}

Table1D pulse_table(const io::CsvTable& table, const std::string& path) {
  const CsvColumns c = two_columns(table, path, "time_s", "stress_pa");
  require_increasing(path, c, c.x, "time_s");
  Table1D t;
  t.x = c.x;
  t.y = c.y;
  return t;
}

Table1D load_strain_rate_table(const std::string& path) {
  return strain_rate_table(io::read_csv(path), path);
}

Table1D strain_rate_table(const io::CsvTable& table, const std::string& path) {
  const CsvColumns c = two_columns(table, path, "time_s", "strain_rate");
  if (!c.header.empty() && (c.header[0] != "time_s" || c.header[1] != "strain_rate"))
    throw InputError(path, "",
                     "the header must read time_s,strain_rate (1/s), got " + c.header[0] + "," +
                         c.header[1]);
  require_increasing(path, c, c.x, "time_s");
  if (c.x[0] < 0)
    throw InputError(path, at_line(c.line[0]),
                     "time_s must start at >= 0 (the run starts at t = 0), got " + show(c.x[0]));
  Table1D t;
  t.x = c.x;
  t.y = c.y;
  return t;
}

Table1D load_loading_curve(const std::string& path) {
  return loading_curve(io::read_csv(path), path);
}

Table1D loading_curve(const io::CsvTable& table, const std::string& path) {
  const CsvColumns c = two_columns(table, path, "strain", "stress_pa");
  if (c.x[0] != 0.0 || c.y[0] != 0.0)
    throw InputError(
        path, at_line(c.line[0]),
        "the loading curve must start at (0, 0), got (" + show(c.x[0]) + ", " + show(c.y[0]) + ")");
  require_increasing(path, c, c.x, "strain");
  require_increasing(path, c, c.y, "stress_pa");
  Table1D t;
  t.x = c.x;
  t.y = c.y;
  t.extrapolate = true;
  return t;
}

}  // namespace kolsky::scene
