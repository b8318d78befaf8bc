#include "fe/mesh.hpp"

#include <numbers>
#include <stdexcept>
#include <string>

namespace kolsky::fe {

std::size_t Nodes::add(double r, double z) {
  r0.push_back(r);
  z0.push_back(z);
  for (auto* v : {&ur, &uz, &ur_prev, &uz_prev, &vr, &vz, &fr_int, &fz_int, &fr_ext, &fz_ext, &mass})
    v->push_back(0.0);
  // The axis is a symmetry line: no radial motion there (u_r/r stays finite).
  fixed_r.push_back(r == 0.0 ? 1 : 0);
  fixed_z.push_back(0);
  return r0.size() - 1;
}

Block add_block(Mesh& mesh, double r_in, double r_out, double z_lo, double z_hi, int n_r, int n_z) {
  if (!(r_in >= 0.0) || !(r_out > r_in) || !(z_hi > z_lo))
    throw std::invalid_argument("fe block needs 0 <= r_in < r_out and z_lo < z_hi");
  if (n_r < 1 || n_z < 1)
    throw std::invalid_argument("fe block needs n_r, n_z >= 1 (got " + std::to_string(n_r) +
                                ", " + std::to_string(n_z) + ")");
  Block b;
  b.first_node = static_cast<int>(mesh.nodes.size());
  b.first_element = static_cast<int>(mesh.quads.size());
  b.n_r = n_r;
  b.n_z = n_z;
  for (int j = 0; j <= n_z; ++j)
    for (int i = 0; i <= n_r; ++i) {
      // Stations computed from the ends so the outer surface lands exactly on r_out, z_hi.
      const double r = i == n_r ? r_out : r_in + (r_out - r_in) * i / n_r;
      const double z = j == n_z ? z_hi : z_lo + (z_hi - z_lo) * j / n_z;
      mesh.nodes.add(r, z);
    }
  for (int j = 0; j < n_z; ++j)
    for (int i = 0; i < n_r; ++i)
      mesh.quads.push_back({b.node(i, j), b.node(i + 1, j), b.node(i + 1, j + 1), b.node(i, j + 1)});
  return b;
}

std::vector<double> ring_tributary_areas(const std::vector<double>& r) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  std::vector<double> a(r.size(), 0.0);
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    const double d = r[i + 1] - r[i];
    a[i] += kTwoPi * d * (2.0 * r[i] + r[i + 1]) / 6.0;
    a[i + 1] += kTwoPi * d * (r[i] + 2.0 * r[i + 1]) / 6.0;
  }
  return a;
}

void Mesh::build_incidence() {
  const std::size_t n = nodes.size();
  incidence_start.assign(n + 1, 0);
  for (const auto& q : quads)
    for (int a : q) ++incidence_start[static_cast<std::size_t>(a) + 1];
  for (std::size_t i = 0; i < n; ++i) incidence_start[i + 1] += incidence_start[i];
  incidence.assign(static_cast<std::size_t>(incidence_start[n]), 0);
  std::vector<int> fill(incidence_start.begin(), incidence_start.end() - 1);
  for (std::size_t e = 0; e < quads.size(); ++e)
    for (int a = 0; a < 4; ++a)
      incidence[static_cast<std::size_t>(fill[static_cast<std::size_t>(quads[e][a])]++)] =
          static_cast<int>(4 * e) + a;
}

void current_coordinates(const Mesh& m, int e, std::array<double, 4>& r, std::array<double, 4>& z) {
  const auto& q = m.quads[static_cast<std::size_t>(e)];
  for (int a = 0; a < 4; ++a) {
    const auto i = static_cast<std::size_t>(q[a]);
    r[a] = m.nodes.r(i);
    z[a] = m.nodes.z(i);
  }
}

}  // namespace kolsky::fe
