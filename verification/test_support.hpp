// Small helpers shared by the GoogleTest files: a per-test scratch directory, a way to attach
// measured numbers to a test's XML/JSON output, and the InputError a call throws.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iterator>
#include <string>

#include "core/errors.hpp"

namespace kolsky::testing {

/// The InputError f throws; a test failure if it throws none.
template <class F>
InputError input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("", "", "");
}

/// A fresh directory per test (named after the test and the process), removed afterwards.
class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "kolsky_test") {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            (prefix + "_" + std::string(info ? info->name() : "none") + "_" +
             std::to_string(getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string str() const { return path_.string(); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  size_t n_entries() const {
    return static_cast<size_t>(std::distance(std::filesystem::directory_iterator(path_),
                                             std::filesystem::directory_iterator()));
  }

 private:
  std::filesystem::path path_;
};

/// Records a measured value as a test property (shown by --gtest_output=json/xml).
inline void record(const std::string& key, double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4e", value);
  ::testing::Test::RecordProperty(key, buf);
}

}  // namespace kolsky::testing
