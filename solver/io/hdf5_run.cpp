// HDF5 run files through the serial C API (layout in hdf5_run.hpp). Every HDF5 handle is owned by
// a small RAII wrapper so an exception part-way through closes everything before the temporary
// file is removed. HDF5's own error printing is switched off; the innermost message of its error
// stack is folded into our exception text instead, so failures read as one line naming the file.
#include "io/hdf5_run.hpp"

#include "core/atomic_file.hpp"
#include "io/h5_util.hpp"
#include "core/build_info.hpp"

#include <hdf5.h>

#include <cstdio>
#include <set>
#include <stdexcept>
#include <utility>


namespace kolsky::io {
namespace {

using h5::check;
using h5::fail;
using h5::Handle;

// ---- writing ----

void write_string_attr(hid_t obj, const std::string& name, const std::string& value) {
  // Variable-length strings live in the global heap, so a large resolved scene does not hit the
  // 64 KiB limit on compact attribute storage.
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type.get(), H5T_VARIABLE), "string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "string type");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attr(H5Acreate2(obj, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose, "create attribute " + name);
  const char* p = value.c_str();
  check(H5Awrite(attr.get(), type.get(), &p), "write attribute " + name);
}

void write_int_attr(hid_t obj, const std::string& name, int value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attr(H5Acreate2(obj, name.c_str(), H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose, "create attribute " + name);
  check(H5Awrite(attr.get(), H5T_NATIVE_INT, &value), "write attribute " + name);
}

void write_vector(hid_t group, const std::string& name, const std::vector<double>& v,
                  const std::string& unit) {
  h5::write_doubles(group, name, v);  // an empty probe is a valid zero-length dataset
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  write_string_attr(set.get(), "unit", unit);
}

/// meta[key] as attribute text: strings verbatim, anything else as JSON, fallback if absent.
std::string meta_text(const nlohmann::json& meta, const char* key, const std::string& fallback) {
  const auto it = meta.find(key);
  if (it == meta.end()) return fallback;
  return it->is_string() ? it->get<std::string>() : it->dump();
}

int meta_complete(const nlohmann::json& meta) {
  const auto it = meta.find("complete");
  if (it == meta.end()) return 0;  // a writer that does not say so has not finished
  if (it->is_boolean()) return it->get<bool>() ? 1 : 0;
  if (it->is_number()) return it->get<double>() != 0.0 ? 1 : 0;
  throw std::runtime_error("meta.complete must be a boolean or a number");
}

void write_meta(hid_t file, const nlohmann::json& meta) {
  Handle group(H5Gcreate2(file, "/meta", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
               "create /meta");
  const auto scene = meta.find("scene");
  write_string_attr(group.get(), "scene", scene == meta.end() ? "null" : scene->dump());
  write_string_attr(group.get(), "git_commit", meta_text(meta, "git_commit", build_info::git_commit()));
  write_string_attr(group.get(), "build_type", meta_text(meta, "build_type", build_info::build_type()));
  write_string_attr(group.get(), "kolsky_version",
                    meta_text(meta, "kolsky_version", build_info::version()));
  write_string_attr(group.get(), "failure", meta_text(meta, "failure", ""));
  write_int_attr(group.get(), "complete", meta_complete(meta));
  write_string_attr(group.get(), "meta_json", meta.dump());
}

void write_probes(hid_t file, const std::vector<Series>& probes) {
  // Track creation order so probes come back in the order the run declared them.
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "group property list");
  check(H5Pset_link_creation_order(gcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "link creation order");
  Handle group(H5Gcreate2(file, "/probes", H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose,
               "create /probes");
  for (const Series& s : probes) {
    Handle g(H5Gcreate2(group.get(), s.name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Gclose, "create /probes/" + s.name);
    write_vector(g.get(), "t", s.t, "s");
    write_vector(g.get(), "value", s.value, s.unit);
  }
}

void validate(const RunRecord& rec) {
  if (!rec.meta.is_object() && !rec.meta.is_null())
    throw std::runtime_error("meta must be a JSON object");
  std::set<std::string> seen;
  for (const Series& s : rec.probes) {
    if (s.name.empty() || s.name == "." || s.name.find('/') != std::string::npos)
      throw std::runtime_error("probe name '" + s.name + "' must be non-empty and contain no '/'");
    if (!seen.insert(s.name).second) throw std::runtime_error("duplicate probe name '" + s.name + "'");
    if (s.t.size() != s.value.size())
      throw std::runtime_error("probe '" + s.name + "': t has " + std::to_string(s.t.size()) +
                        " samples but value has " + std::to_string(s.value.size()));
  }
}

// ---- reading ----

bool has_attr(hid_t obj, const char* name) { return H5Aexists(obj, name) > 0; }

std::string read_string_attr(hid_t obj, const std::string& name) {
  Handle attr(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  Handle ftype(H5Aget_type(attr.get()), H5Tclose, "type of attribute " + name);
  if (H5Tget_class(ftype.get()) != H5T_STRING)
    throw std::runtime_error("attribute " + name + " is not a string");
  Handle mtype(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get())), "string type");
  if (H5Tis_variable_str(ftype.get()) > 0) {
    check(H5Tset_size(mtype.get(), H5T_VARIABLE), "string type");
    char* p = nullptr;
    check(H5Aread(attr.get(), mtype.get(), &p), "read attribute " + name);
    std::string s = p != nullptr ? p : "";
    H5free_memory(p);
    return s;
  }
  // Fixed-length strings (other writers): read with room for a terminator, then trim padding.
  const size_t n = H5Tget_size(ftype.get());
  check(H5Tset_size(mtype.get(), n + 1), "string type");
  std::string buf(n + 1, '\0');
  check(H5Aread(attr.get(), mtype.get(), buf.data()), "read attribute " + name);
  buf.resize(buf.find('\0') == std::string::npos ? n : buf.find('\0'));
  while (!buf.empty() && buf.back() == ' ') buf.pop_back();
  return buf;
}

int read_int_attr(hid_t obj, const std::string& name) {
  Handle attr(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  int v = 0;
  check(H5Aread(attr.get(), H5T_NATIVE_INT, &v), "read attribute " + name);
  return v;
}

std::vector<double> read_vector(hid_t group, const std::string& name, std::string* unit) {
  Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  Handle space(H5Dget_space(set.get()), H5Sclose, "dataspace of " + name);
  if (H5Sget_simple_extent_ndims(space.get()) != 1)
    throw std::runtime_error("dataset " + name + " is not one-dimensional");
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  if (n < 0) fail("size of dataset " + name);
  std::vector<double> v(static_cast<size_t>(n));
  if (n > 0)
    check(H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
          "read dataset " + name);
  if (unit != nullptr) *unit = has_attr(set.get(), "unit") ? read_string_attr(set.get(), "unit") : "";
  return v;
}

nlohmann::json read_meta(hid_t file) {
  Handle group(H5Gopen2(file, "/meta", H5P_DEFAULT), H5Gclose, "open /meta");
  if (has_attr(group.get(), "meta_json")) {
    const std::string text = read_string_attr(group.get(), "meta_json");
    try {
      return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
      throw std::runtime_error(std::string("/meta/meta_json is not valid JSON: ") + e.what());
    }
  }
  // Older or foreign files: rebuild what the individual attributes carry.
  nlohmann::json meta = nlohmann::json::object();
  for (const char* key : {"git_commit", "build_type", "kolsky_version", "failure"})
    if (has_attr(group.get(), key)) meta[key] = read_string_attr(group.get(), key);
  if (has_attr(group.get(), "scene")) {
    const std::string text = read_string_attr(group.get(), "scene");
    nlohmann::json scene = nlohmann::json::parse(text, nullptr, false);
    meta["scene"] = scene.is_discarded() ? nlohmann::json(text) : std::move(scene);
  }
  if (has_attr(group.get(), "complete")) meta["complete"] = read_int_attr(group.get(), "complete") != 0;
  return meta;
}

std::vector<Series> read_probes(hid_t file) {
  std::vector<Series> probes;
  if (H5Lexists(file, "/probes", H5P_DEFAULT) <= 0) return probes;
  Handle group(H5Gopen2(file, "/probes", H5P_DEFAULT), H5Gclose, "open /probes");
  Handle gcpl(H5Gget_create_plist(group.get()), H5Pclose, "/probes creation properties");
  unsigned order_flags = 0;
  check(H5Pget_link_creation_order(gcpl.get(), &order_flags), "/probes creation order");
  const H5_index_t index =
      (order_flags & H5P_CRT_ORDER_INDEXED) != 0 ? H5_INDEX_CRT_ORDER : H5_INDEX_NAME;
  H5G_info_t info;
  check(H5Gget_info(group.get(), &info), "list /probes");
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len =
        H5Lget_name_by_idx(group.get(), ".", index, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) fail("name of probe " + std::to_string(i));
    std::string name(static_cast<size_t>(len) + 1, '\0');
    if (H5Lget_name_by_idx(group.get(), ".", index, H5_ITER_INC, i, name.data(), name.size(),
                           H5P_DEFAULT) < 0)
      fail("name of probe " + std::to_string(i));
    name.resize(static_cast<size_t>(len));
    Handle g(H5Gopen2(group.get(), name.c_str(), H5P_DEFAULT), H5Gclose, "open /probes/" + name);
    Series s;
    s.name = name;
    s.t = read_vector(g.get(), "t", nullptr);
    s.value = read_vector(g.get(), "value", &s.unit);
    if (s.t.size() != s.value.size())
      throw std::runtime_error("probe '" + name + "': t and value differ in length");
    probes.push_back(std::move(s));
  }
  return probes;
}

}  // namespace

void write_run_hdf5(const std::string& path, const RunRecord& rec) {
  h5::silence();
  const std::string tmp = temporary_name(path);
  try {
    validate(rec);
    const nlohmann::json meta = rec.meta.is_null() ? nlohmann::json::object() : rec.meta;
    Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                "create " + tmp);
    write_meta(file.get(), meta);
    write_probes(file.get(), rec.probes);
    file.close("close " + tmp);
  } catch (const std::exception& e) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write HDF5 run file " + path + ": " + e.what());
  }
  commit_file(tmp, path);  // removes tmp and names both paths if the rename fails
}

RunRecord read_run_hdf5(const std::string& path) {
  h5::silence();
  try {
    Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open");
    RunRecord rec;
    rec.meta = read_meta(file.get());
    rec.probes = read_probes(file.get());
    return rec;
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot read HDF5 run file " + path + ": " + e.what());
  }
}

}  // namespace kolsky::io
