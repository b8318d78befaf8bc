// Numeric CSV reader/writer (format in csv.hpp). Numbers are parsed with std::from_chars so the
// result does not depend on the process locale (a German locale would otherwise read "1.5" as 1).
#include "io/csv.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace kolsky::io {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  if (line.find(',') == std::string::npos) {  // blank-separated row
    while (in >> cell) cells.push_back(cell);
    return cells;
  }
  while (std::getline(in, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();  // getline drops a trailing empty cell
  return cells;
}

/// Whole-cell number parse; from_chars rejects a leading '+', which is common in exported data.
bool parse_number(const std::string& cell, double& out) {
  const char* first = cell.data();
  const char* last = cell.data() + cell.size();
  if (first != last && *first == '+') ++first;
  if (first == last) return false;
  const auto [ptr, ec] = std::from_chars(first, last, out);
  return ec == std::errc() && ptr == last;
}

std::string line_ref(size_t line_no) { return "line " + std::to_string(line_no); }

const char* const kDecimalCommaHint =
    ": fields are separated by commas or blanks and the decimal point is '.' (a decimal-comma "
    "or ';'-separated export? convert it)";

}  // namespace

size_t CsvTable::rows() const { return columns.empty() ? 0 : columns.front().size(); }

const std::vector<double>& CsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < header.size() && i < columns.size(); ++i)
    if (header[i] == name) return columns[i];
  std::string available;
  for (const auto& h : header) available += (available.empty() ? "" : ", ") + h;
  throw std::out_of_range("no column '" + name + "' (available: " +
                          (available.empty() ? "none, the table has no header" : available) + ")");
}

CsvTable read_csv(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "is a directory, not a CSV file");
  std::ifstream in(path);
  if (!in) throw InputError(path, "", std::string("cannot open: ") + std::strerror(errno));
  return parse_csv(in, path);
}

CsvTable parse_csv(std::istream& in, const std::string& path) {
  CsvTable t;
  bool first_row = true;
  size_t line_no = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string content = trim(line);
    if (content.empty()) continue;
    if (content.front() == '#') {
      t.comments.push_back(trim(content.substr(1)));
      continue;
    }
    const std::vector<std::string> cells = split_cells(content);
    std::vector<double> values(cells.size());
    size_t first_bad = cells.size();
    for (size_t i = 0; i < cells.size() && first_bad == cells.size(); ++i)
      if (!parse_number(cells[i], values[i])) first_bad = i;

    if (first_row) {
      first_row = false;
      t.columns.resize(cells.size());
      if (first_bad != cells.size()) {  // any non-numeric cell: this row names the columns
        // A header names columns; one with numbers among its names, or a ';', is almost
        // always a decimal-comma export ("0,5;1,2" splits into '0', '5;1', '2'), which would
        // otherwise be reported as a duplicate or a mismatched column.
        bool numeric_name = first_bad > 0;  // the cells before first_bad are numbers
        for (size_t i = first_bad + 1; i < cells.size() && !numeric_name; ++i)
          numeric_name = parse_number(cells[i], values[i]);
        if (numeric_name || content.find(';') != std::string::npos)
          throw InputError(path, line_ref(line_no),
                           "'" + content + "' mixes numbers and text" + kDecimalCommaHint);
        std::set<std::string> seen;
        for (size_t i = 0; i < cells.size(); ++i) {
          if (cells[i].empty())
            throw InputError(path, line_ref(line_no), "header column " + std::to_string(i + 1) +
                                                          " has an empty name");
          if (!seen.insert(cells[i]).second)
            throw InputError(path, line_ref(line_no), "duplicate column name '" + cells[i] + "'");
        }
        t.header = cells;
        continue;
      }
    }
    if (cells.size() != t.columns.size())
      throw InputError(path, line_ref(line_no),
                       "row has " + std::to_string(cells.size()) + " cells but the table has " +
                           std::to_string(t.columns.size()) + " columns");
    if (first_bad != cells.size()) {
      const std::string col = t.header.empty() ? "column " + std::to_string(first_bad + 1)
                                               : "column '" + t.header[first_bad] + "'";
      throw InputError(path, line_ref(line_no),
                       col + ": '" + cells[first_bad] + "' is not a number" +
                           (content.find(';') != std::string::npos ? kDecimalCommaHint : ""));
    }
    for (size_t i = 0; i < values.size(); ++i) t.columns[i].push_back(values[i]);
    t.lines.push_back(line_no);
  }
  if (in.bad()) throw InputError(path, line_ref(line_no), "read error");
  if (first_row) throw InputError(path, "", "empty file: no header or data rows");
  return t;
}

void write_csv(const std::string& path, const CsvTable& t, const std::string& comment) {
  const size_t n_rows = t.rows();
  if (!t.header.empty() && t.header.size() != t.columns.size())
    throw std::invalid_argument(path + ": header has " + std::to_string(t.header.size()) +
                                " names but the table has " + std::to_string(t.columns.size()) +
                                " columns");
  for (size_t i = 0; i < t.columns.size(); ++i)
    if (t.columns[i].size() != n_rows)
      throw std::invalid_argument(path + ": column " + std::to_string(i + 1) + " has " +
                                  std::to_string(t.columns[i].size()) + " rows, expected " +
                                  std::to_string(n_rows));
  bool all_numeric = !t.header.empty();
  for (const auto& h : t.header) {
    // Anything the reader would trim, split or skip would not survive a round trip.
    if (h.empty() || trim(h) != h || h.front() == '#' ||
        h.find_first_of(",\n\r") != std::string::npos)
      throw std::invalid_argument(path + ": column name '" + h +
                                  "' must be non-empty, not start with '#', and have no "
                                  "surrounding spaces, commas or line breaks");
    double ignored = 0.0;
    all_numeric = all_numeric && parse_number(h, ignored);
  }
  if (all_numeric)
    throw std::invalid_argument(path + ": every column name is a number, so the header would be "
                                "read back as a data row");

  std::string out;
  if (!comment.empty()) {
    std::istringstream lines(comment);
    std::string line;
    while (std::getline(lines, line)) out += "# " + line + "\n";
  }
  for (size_t i = 0; i < t.header.size(); ++i) out += (i ? "," : "") + t.header[i];
  if (!t.header.empty()) out += "\n";
  char buf[40];
  for (size_t r = 0; r < n_rows; ++r) {
    for (size_t c = 0; c < t.columns.size(); ++c) {
      // to_chars(general, 10) is %.10g without the locale's decimal separator.
      const auto res = std::to_chars(buf, buf + sizeof buf, t.columns[c][r],
                                     std::chars_format::general, 10);
      if (c) out += ",";
      out.append(buf, res.ptr);
    }
    out += "\n";
  }
  write_file_atomic(path, out);
}

}  // namespace kolsky::io
