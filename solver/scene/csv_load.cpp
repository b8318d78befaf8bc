#include "scene/csv_load.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/errors.hpp"

namespace kolsky::scene {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  if (line.find(',') != std::string::npos) {
    size_t start = 0;
    while (true) {
      const auto comma = line.find(',', start);
      fields.push_back(
          trim(line.substr(start, comma == std::string::npos ? comma : comma - start)));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  } else {
    size_t start = line.find_first_not_of(" \t");
    while (start != std::string::npos) {
      const auto end = line.find_first_of(" \t", start);
      fields.push_back(line.substr(start, end == std::string::npos ? end : end - start));
      start = end == std::string::npos ? end : line.find_first_not_of(" \t", end);
    }
  }
  return fields;
}

/// Strict full-field parse; false for text, trailing junk, overflow or non-finite values.
bool parse_number(const std::string& field, double& out) {
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (begin != end && *begin == '+') ++begin;  // from_chars rejects a leading '+'
  const auto [ptr, ec] = std::from_chars(begin, end, out);
  return ec == std::errc() && ptr == end && begin != end && std::isfinite(out);
}

std::string show(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string at_line(size_t line) { return "line " + std::to_string(line); }

}  // namespace

CsvColumns read_two_column_csv(const std::string& path, const std::string& x_name,
                               const std::string& y_name) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open the file");
  CsvColumns c;
  bool first_row = true;
  std::string raw;
  for (size_t line = 1; std::getline(in, raw); ++line) {
    const std::string text = trim(raw);
    if (text.empty() || text[0] == '#') continue;
    const std::vector<std::string> fields = split_fields(text);
    const bool header_allowed = first_row;
    first_row = false;
    double v[2] = {0.0, 0.0};
    const bool numeric =
        fields.size() == 2 && parse_number(fields[0], v[0]) && parse_number(fields[1], v[1]);
    if (!numeric && header_allowed) {
      // A header row such as "time_s,stress_pa": every field is text. A row mixing numbers
      // and text is a broken data row and is reported below.
      bool all_text = true;
      double ignored = 0.0;
      for (const auto& f : fields) all_text = all_text && !parse_number(f, ignored);
      if (all_text) continue;
    }
    if (fields.size() != 2)
      throw InputError(path, at_line(line),
                       "expected 2 columns (" + x_name + ", " + y_name + "), found " +
                           std::to_string(fields.size()));
    for (int k = 0; k < 2; ++k)
      if (!parse_number(fields[k], v[k]))
        throw InputError(path, at_line(line),
                         "'" + fields[k] + "' is not a finite number (column " +
                             (k == 0 ? x_name : y_name) + ")");
    c.x.push_back(v[0]);
    c.y.push_back(v[1]);
    c.line.push_back(line);
  }
  if (c.x.size() < 2)
    throw InputError(path, "",
                     "needs at least 2 data rows (" + x_name + ", " + y_name + "), found " +
                         std::to_string(c.x.size()));
  return c;
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
  const CsvColumns c = read_two_column_csv(path, "time_s", "stress_pa");
  require_increasing(path, c, c.x, "time_s");
  Table1D t;
  t.x = c.x;
  t.y = c.y;
  return t;
}

Table1D load_loading_curve(const std::string& path) {
  const CsvColumns c = read_two_column_csv(path, "strain", "stress_pa");
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
