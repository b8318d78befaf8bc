#include "core/table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kolsky {

void Table1D::validate() const {
  if (x.size() != y.size()) throw std::invalid_argument("x and y columns differ in length");
  if (x.size() < 2) throw std::invalid_argument("needs at least 2 rows");
  for (size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw std::invalid_argument("non-finite value in row " + std::to_string(i + 1));
    if (i > 0 && !(x[i] > x[i - 1]))
      throw std::invalid_argument("first column must be strictly increasing (row " +
                                  std::to_string(i + 1) + ")");
  }
}

static size_t segment(const std::vector<double>& x, double xq) {
  auto it = std::upper_bound(x.begin(), x.end(), xq);
  size_t i = static_cast<size_t>(it - x.begin());
  if (i == 0) return 0;
  if (i >= x.size()) return x.size() - 2;
  return i - 1;
}

double Table1D::operator()(double xq) const {
  if (!extrapolate) {
    if (xq <= x.front()) return y.front();
    if (xq >= x.back()) return y.back();
  }
  const size_t i = segment(x, xq);
  const double w = (xq - x[i]) / (x[i + 1] - x[i]);
  return y[i] + w * (y[i + 1] - y[i]);
}

double Table1D::slope(double xq) const {
  const size_t i = segment(x, xq);
  return (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
}

double interp_uniform(const std::vector<double>& y, double t0, double dt, double t) {
  if (y.empty()) return 0.0;
  const double s = (t - t0) / dt;
  if (s <= 0.0) return y.front();
  const double last = static_cast<double>(y.size() - 1);
  if (s >= last) return y.back();
  const size_t i = static_cast<size_t>(s);
  const double w = s - static_cast<double>(i);
  return y[i] + w * (y[i + 1] - y[i]);
}

}  // namespace kolsky
