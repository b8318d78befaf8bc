#include "sweep/sweep_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "io/h5_util.hpp"
#include "scene/scene_change.hpp"
#include "sweep/sweep_run.hpp"

namespace kolsky::sweep {

namespace {

Column numbers(std::string name) { return {std::move(name), false, {}, {}}; }
Column texts(std::string name) { return {std::move(name), true, {}, {}}; }

double number_or_nan(const nlohmann::json& v) { return v.is_number() ? v.get<double>() : NAN; }

// RFC 4180: a cell holding a comma, quote or line break is quoted, its quotes doubled.
std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

std::string csv_cell(const Column& c, std::size_t row) {
  if (!c.text) return std::isnan(c.numbers[row]) ? "nan" : value_text(c.numbers[row]);
  return quoted(c.texts[row]);
}

}  // namespace

const Column& SweepTable::column(const std::string& name) const {
  for (const Column& c : columns)
    if (c.name == name) return c;
  throw std::out_of_range("the sweep table has no column '" + name + "'");
}

SweepTable make_table(const SweepPlan& plan, const std::vector<SweepPoint>& points,
                      const std::vector<ensemble::MemberResult>& results) {
  if (results.size() != points.size()) throw std::invalid_argument("make_table: one result per member");
  SweepTable t;
  t.rows = points.size();
  Column member = numbers("member");
  for (std::size_t i = 0; i < t.rows; ++i) member.numbers.push_back(static_cast<double>(i + 1));
  t.columns.push_back(std::move(member));
  nlohmann::json keys = nlohmann::json::array();
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    bool numeric = true;
    for (const auto& v : plan.axes[k].values) numeric = numeric && v.is_number();
    Column c = numeric ? numbers(plan.axes[k].key) : texts(plan.axes[k].key);
    for (const SweepPoint& p : points) {
      if (numeric) c.numbers.push_back(p.values[k].get<double>());
      else c.texts.push_back(value_text(p.values[k]));
    }
    t.columns.push_back(std::move(c));
    keys.push_back({{"key", plan.axes[k].key}, {"values", plan.axes[k].values}, {"log_spaced", plan.axes[k].log_spaced}});
  }
  if (plan.seeds > 0) {
    Column c = numbers("seed");
    for (const SweepPoint& p : points) c.numbers.push_back(p.seed);
    t.columns.push_back(std::move(c));
  }
  // The summary figures: a direct analysis (strain-rate walls) has other keys than a wave one.
  std::vector<std::string> figures;
  for (const auto& r : results)
    if (r.ok && r.value.contains("summary"))
      for (const auto& [k, v] : r.value.at("summary").items())
        if (std::find(figures.begin(), figures.end(), k) == figures.end()) figures.push_back(k);
  for (const std::string& f : figures) {
    Column c = numbers(f);
    for (const auto& r : results)
      c.numbers.push_back(r.ok && r.value.contains("summary") ? number_or_nan(r.value["summary"].value(f, nlohmann::json()))
                                                             : NAN);
    t.columns.push_back(std::move(c));
  }
  Column steps = numbers("steps"), run_s = numbers("run_s");
  Column status = texts("status"), kind = texts("failure_kind"), error = texts("error"), key = texts("key");
  for (std::size_t i = 0; i < t.rows; ++i) {
    const MemberOutcome o = outcome(results[i]);
    steps.numbers.push_back(results[i].ok ? number_or_nan(results[i].value.value("steps", nlohmann::json())) : NAN);
    run_s.numbers.push_back(o.run_s);
    status.texts.push_back(o.ok ? "ok" : "failed");
    kind.texts.push_back(o.failure_kind);
    error.texts.push_back(o.error);
    key.texts.push_back(results[i].key);
  }
  for (Column* c : {&steps, &run_s, &status, &kind, &error, &key}) t.columns.push_back(std::move(*c));
  t.meta = {{"scene_file", plan.scene_file}, {"axes", keys},          {"seeds", plan.seeds},
            {"figures", figures},            {"members", t.rows},     {"kolsky", scene::binary_version()}};
  return t;
}

std::string csv_text(const SweepTable& t) {
  std::string out;
  for (std::size_t c = 0; c < t.columns.size(); ++c) out += (c ? "," : "") + quoted(t.columns[c].name);
  out += "\n";
  for (std::size_t r = 0; r < t.rows; ++r) {
    for (std::size_t c = 0; c < t.columns.size(); ++c) out += (c ? "," : "") + csv_cell(t.columns[c], r);
    out += "\n";
  }
  return out;
}

void write_table_csv(const std::string& path, const SweepTable& t) {
  try {
    write_file_atomic(path, csv_text(t));
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write the sweep table " + path + ": " + e.what());
  }
}

void write_table_hdf5(const std::string& path, const SweepTable& t) {
  namespace h5 = io::h5;
  h5::write_file_atomic(path, "the sweep table", [&](hid_t file) {
    h5::write_attr(h5::create_group(file, "meta").get(), "meta_json", t.meta.dump());
    const h5::Handle table = h5::create_group(file, "table");
    nlohmann::json order = nlohmann::json::array();
    for (const Column& c : t.columns) {
      order.push_back({{"name", c.name}, {"text", c.text}});
      if (c.text) h5::write_strings(table.get(), c.name, c.texts);
      else h5::write_doubles(table.get(), c.name, c.numbers);
    }
    h5::write_attr(table.get(), "columns", order.dump());
  });
}

SweepTable read_table_hdf5(const std::string& path) {
  namespace h5 = io::h5;
  h5::silence();
  try {
    h5::Handle file = h5::open_file_read(path);
    SweepTable t;
    t.meta = nlohmann::json::parse(h5::read_attr_string(h5::open_group(file.get(), "meta").get(), "meta_json"));
    h5::Handle table = h5::open_group(file.get(), "table");
    for (const auto& col : nlohmann::json::parse(h5::read_attr_string(table.get(), "columns"))) {
      Column c{col.at("name").get<std::string>(), col.at("text").get<bool>(), {}, {}};
      if (c.text) c.texts = h5::read_strings(table.get(), c.name);
      else c.numbers = h5::read_doubles(table.get(), c.name);
      t.rows = c.text ? c.texts.size() : c.numbers.size();
      t.columns.push_back(std::move(c));
    }
    return t;
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read the sweep table " + path + ": " + e.what());
  }
}

std::vector<std::string> figure_columns(const SweepTable& t) {
  return t.meta.value("figures", std::vector<std::string>());
}

}  // namespace kolsky::sweep
