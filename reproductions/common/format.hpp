// printf-style formatting of one number for report notes and tables, shared by the drivers.
#pragma once
#include <cstdio>
#include <string>

namespace kolsky::repro {

/// fmt("%.1f MPa", 2.5e1) -> "25.0 MPa"; f must take exactly one double.
inline std::string fmt(const char* f, double a) {
  char buf[128];
  std::snprintf(buf, sizeof buf, f, a);
  return buf;
}

}  // namespace kolsky::repro
