#include "core/atomic_file.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace kolsky {

std::string temporary_name(const std::string& path) {
  return path + ".tmp." + std::to_string(static_cast<long>(getpid()));
}

void commit_file(const std::string& tmp, const std::string& final_path) {
  if (std::rename(tmp.c_str(), final_path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename " + tmp + " to " + final_path);
  }
}

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = temporary_name(path);
  {
    std::ofstream f(tmp, std::ios::binary);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    f << content;
    if (!f) throw std::runtime_error("write failed: " + tmp);
  }
  commit_file(tmp, path);
}

}  // namespace kolsky
