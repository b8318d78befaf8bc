// See h5_util.hpp.
#include "io/h5_util.hpp"

#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/atomic_file.hpp"

namespace kolsky::io::h5 {

namespace {

herr_t innermost(unsigned n, const H5E_error2_t* err, void* out) {
  if (n == 0 && err != nullptr && err->desc != nullptr) *static_cast<std::string*>(out) = err->desc;
  return 0;
}

Handle scalar_space() { return Handle(H5Screate(H5S_SCALAR), H5Sclose, "scalar dataspace"); }

Handle open_dataset(hid_t loc, const std::string& name, std::vector<hsize_t>& dims) {
  Handle set(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  Handle space(H5Dget_space(set.get()), H5Sclose, "dataspace of " + name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail("rank of " + name);
  dims.assign(static_cast<std::size_t>(rank), 0);
  if (rank > 0) H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return set;
}

// Variable-length UTF-8: a resolved scene may exceed the 64 KiB compact-attribute limit, and a
// table's text column has no common length.
Handle utf8_string_type() {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type.get(), H5T_VARIABLE), "string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "string type");
  return type;
}

}  // namespace

[[noreturn]] void fail(const std::string& what) {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, &detail);
  H5Eclear2(H5E_DEFAULT);
  throw std::runtime_error(detail.empty() ? what : what + ": " + detail);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

Handle::Handle(hid_t id, Closer closer, const std::string& what) : id_(id), closer_(closer) {
  if (id_ < 0) fail(what);
}
Handle::Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, -1)), closer_(o.closer_) {}
Handle& Handle::operator=(Handle&& o) noexcept {
  if (this != &o) {
    if (id_ >= 0) closer_(id_);
    id_ = std::exchange(o.id_, -1);
    closer_ = o.closer_;
  }
  return *this;
}
Handle::~Handle() {
  if (id_ >= 0) closer_(id_);
}
void Handle::close(const std::string& what) {
  const hid_t id = std::exchange(id_, -1);
  check(closer_(id), what);
}

void silence() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

void write_file_atomic(const std::string& path, const std::string& what, const std::function<void(hid_t)>& fill) {
  silence();
  const std::string tmp = temporary_name(path);
  try {
    Handle file = create_file(tmp);
    fill(file.get());
    file.close("close " + tmp);
  } catch (const std::exception& e) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write " + what + " " + path + ": " + e.what());
  }
  commit_file(tmp, path);  // removes tmp and names both paths if the rename fails
}

Handle create_file(const std::string& path) {
  return Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                "create " + path);
}
Handle open_file_read(const std::string& path) {
  return Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open");
}
Handle create_group(hid_t loc, const std::string& name) {
  return Handle(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                "create group " + name);
}
Handle open_group(hid_t loc, const std::string& name) {
  return Handle(H5Gopen2(loc, name.c_str(), H5P_DEFAULT), H5Gclose, "open group " + name);
}
bool exists(hid_t loc, const std::string& name) { return H5Lexists(loc, name.c_str(), H5P_DEFAULT) > 0; }

void write_doubles(hid_t loc, const std::string& name, const double* data, std::size_t rows,
                   std::size_t cols) {
  const hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr), H5Sclose, "dataspace " + name);
  Handle set(H5Dcreate2(loc, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                        H5P_DEFAULT),
             H5Dclose, "create dataset " + name);
  if (rows * cols > 0)  // HDF5 rejects a null buffer; an empty dataset needs no write
    check(H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "write dataset " + name);
}

void write_ints(hid_t loc, const std::string& name, const std::vector<std::int64_t>& v) {
  const hsize_t dims[1] = {v.size()};
  Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose, "dataspace " + name);
  Handle set(H5Dcreate2(loc, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                        H5P_DEFAULT),
             H5Dclose, "create dataset " + name);
  if (!v.empty())
    check(H5Dwrite(set.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
          "write dataset " + name);
}

std::vector<double> read_doubles(hid_t loc, const std::string& name, std::size_t cols) {
  std::vector<hsize_t> dims;
  Handle set = open_dataset(loc, name, dims);
  const bool shape_ok = cols == 1 ? dims.size() == 1 : dims.size() == 2 && dims[1] == cols;
  if (!shape_ok)
    throw std::runtime_error("dataset " + name + " must have " +
                             (cols == 1 ? std::string("one dimension")
                                        : "shape (n, " + std::to_string(cols) + ")"));
  std::vector<double> v(static_cast<std::size_t>(dims[0]) * cols);
  if (!v.empty())
    check(H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
          "read dataset " + name);
  return v;
}

std::vector<std::int64_t> read_ints(hid_t loc, const std::string& name) {
  std::vector<hsize_t> dims;
  Handle set = open_dataset(loc, name, dims);
  if (dims.size() != 1) throw std::runtime_error("dataset " + name + " must have one dimension");
  std::vector<std::int64_t> v(static_cast<std::size_t>(dims[0]));
  if (!v.empty())
    check(H5Dread(set.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
          "read dataset " + name);
  return v;
}

void write_attr(hid_t obj, const std::string& name, double v) {
  Handle space = scalar_space();
  Handle a(H5Acreate2(obj, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose, "create attribute " + name);
  check(H5Awrite(a.get(), H5T_NATIVE_DOUBLE, &v), "write attribute " + name);
}

void write_attr(hid_t obj, const std::string& name, std::int64_t v) {
  Handle space = scalar_space();
  Handle a(H5Acreate2(obj, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose, "create attribute " + name);
  check(H5Awrite(a.get(), H5T_NATIVE_INT64, &v), "write attribute " + name);
}

void write_strings(hid_t loc, const std::string& name, const std::vector<std::string>& v) {
  Handle type = utf8_string_type();
  const hsize_t dims[1] = {v.size()};
  Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose, "dataspace " + name);
  Handle set(H5Dcreate2(loc, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose, "create dataset " + name);
  std::vector<const char*> p;
  for (const std::string& s : v) p.push_back(s.c_str());
  if (!v.empty()) check(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()), "write dataset " + name);
}

std::vector<std::string> read_strings(hid_t loc, const std::string& name) {
  std::vector<hsize_t> dims;
  Handle set = open_dataset(loc, name, dims);
  Handle ftype(H5Dget_type(set.get()), H5Tclose, "type of dataset " + name);
  if (dims.size() != 1 || H5Tget_class(ftype.get()) != H5T_STRING || H5Tis_variable_str(ftype.get()) <= 0)
    throw std::runtime_error("dataset " + name + " is not a list of variable-length strings");
  Handle type = utf8_string_type();
  std::vector<char*> p(static_cast<std::size_t>(dims[0]), nullptr);
  if (!p.empty()) check(H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data()), "read dataset " + name);
  std::vector<std::string> v;
  for (char* c : p) {
    v.emplace_back(c != nullptr ? c : "");
    H5free_memory(c);
  }
  return v;
}

void write_attr(hid_t obj, const std::string& name, const std::string& v) {
  Handle type = utf8_string_type();
  Handle space = scalar_space();
  Handle a(H5Acreate2(obj, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
           H5Aclose, "create attribute " + name);
  const char* p = v.c_str();
  check(H5Awrite(a.get(), type.get(), &p), "write attribute " + name);
}

double read_attr_double(hid_t obj, const std::string& name) {
  Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  double v = 0;
  check(H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  return v;
}

std::int64_t read_attr_int(hid_t obj, const std::string& name) {
  Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  std::int64_t v = 0;
  check(H5Aread(a.get(), H5T_NATIVE_INT64, &v), "read attribute " + name);
  return v;
}

std::string read_attr_string(hid_t obj, const std::string& name) {
  Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  Handle ftype(H5Aget_type(a.get()), H5Tclose, "type of attribute " + name);
  if (H5Tget_class(ftype.get()) != H5T_STRING || H5Tis_variable_str(ftype.get()) <= 0)
    throw std::runtime_error("attribute " + name + " is not a variable-length string");
  Handle mtype(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(mtype.get(), H5T_VARIABLE), "string type");
  check(H5Tset_cset(mtype.get(), H5Tget_cset(ftype.get())), "string type");
  char* p = nullptr;
  check(H5Aread(a.get(), mtype.get(), &p), "read attribute " + name);
  std::string s = p != nullptr ? p : "";
  H5free_memory(p);
  return s;
}

}  // namespace kolsky::io::h5
