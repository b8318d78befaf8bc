// Small RAII layer over the serial HDF5 C API for the checkpoint and snapshot files: groups,
// 1-D and n x k double / int64 datasets, 1-D string datasets, scalar attributes. Every failure throws
// std::runtime_error with the innermost HDF5 message; callers add the file name. Shared by the
// run files (hdf5_run.cpp), checkpoints and snapshots.
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace kolsky::io::h5 {

/// Owns one hid_t and closes it with the matching H5?close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer, const std::string& what);
  Handle(Handle&& o) noexcept;
  Handle& operator=(Handle&& o) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle();
  hid_t get() const { return id_; }
  /// Explicit close (a file's close flushes and can fail).
  void close(const std::string& what);

 private:
  hid_t id_ = -1;
  Closer closer_ = nullptr;
};

/// Throws std::runtime_error("what: <innermost HDF5 message>") and clears the error stack.
[[noreturn]] void fail(const std::string& what);
/// fail(what) when status < 0.
void check(herr_t status, const std::string& what);

/// Switches off HDF5's own error printing (our exceptions carry the message).
void silence();
/// A new file at `path` written whole or not at all: created under a temporary sibling name,
/// filled by `fill(file)`, closed and renamed to `path`; on any failure the temporary is removed,
/// an existing `path` left as it was, and std::runtime_error("cannot write <what> <path>: ...")
/// thrown.
void write_file_atomic(const std::string& path, const std::string& what, const std::function<void(hid_t)>& fill);
Handle create_file(const std::string& path);      ///< truncates
Handle open_file_read(const std::string& path);
Handle create_group(hid_t loc, const std::string& name);
Handle open_group(hid_t loc, const std::string& name);
bool exists(hid_t loc, const std::string& name);

/// rows x cols doubles (cols = 1 writes a 1-D dataset of rows values), row-major.
void write_doubles(hid_t loc, const std::string& name, const double* data, std::size_t rows,
                   std::size_t cols = 1);
inline void write_doubles(hid_t loc, const std::string& name, const std::vector<double>& v) {
  write_doubles(loc, name, v.data(), v.size());
}
void write_ints(hid_t loc, const std::string& name, const std::vector<std::int64_t>& v);
/// Reads a dataset of `cols` columns (1: one-dimensional) as a flat row-major vector; throws
/// when the shape differs.
std::vector<double> read_doubles(hid_t loc, const std::string& name, std::size_t cols = 1);
std::vector<std::int64_t> read_ints(hid_t loc, const std::string& name);
/// A 1-D dataset of variable-length UTF-8 strings (a table's text column), and back.
void write_strings(hid_t loc, const std::string& name, const std::vector<std::string>& v);
std::vector<std::string> read_strings(hid_t loc, const std::string& name);

void write_attr(hid_t obj, const std::string& name, double v);
void write_attr(hid_t obj, const std::string& name, std::int64_t v);
void write_attr(hid_t obj, const std::string& name, const std::string& v);
double read_attr_double(hid_t obj, const std::string& name);
std::int64_t read_attr_int(hid_t obj, const std::string& name);
std::string read_attr_string(hid_t obj, const std::string& name);

}  // namespace kolsky::io::h5
