#include "coupling/surface_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

#include "core/errors.hpp"

namespace kolsky::coupling {

dem::WallProfile face_profile(const fe::Nodes& nd, const std::vector<int>& face, FaceSide side) {
  const double sg = static_cast<double>(static_cast<int>(side));
  dem::WallProfile p;
  for (int node : face) {
    const auto n = static_cast<std::size_t>(node);
    p.station.push_back(nd.r(n));
    p.offset.push_back(sg * nd.uz[n]);
    p.normal_speed.push_back(sg * nd.vz[n]);
    p.tangential_speed.push_back(nd.vr[n]);
  }
  return p;
}

dem::WallProfile tube_profile(const fe::Nodes& nd, const std::vector<int>& wall) {
  dem::WallProfile p;
  for (int node : wall) {
    const auto n = static_cast<std::size_t>(node);
    p.station.push_back(nd.z(n));
    p.offset.push_back(nd.ur[n]);
    p.normal_speed.push_back(nd.vr[n]);
    p.tangential_speed.push_back(nd.vz[n]);
  }
  return p;
}

void add_contact(RingLoads& l, const dem::WallProfile& profile, double s, const dem::Vec3& x,
                 const dem::Vec3& f) {
  const double rho = std::hypot(x.x, x.y);
  // Radial and circumferential unit vectors at the grain (on the axis there is no radial
  // direction: the lateral part of the force is then all off-axis).
  const double cx = rho > 0 ? x.x / rho : 0.0, cy = rho > 0 ? x.y / rho : 0.0;
  const double f_r = f.x * cx + f.y * cy, f_theta = -f.x * cy + f.y * cx;
  const auto [k, w] = profile.segment(s);
  // Linear shape functions of the segment, split so that the two shares add up to the force.
  const double br = w * f_r, bz = w * f.z;
  l.f_r[static_cast<std::size_t>(k)] += f_r - br;
  l.f_r[static_cast<std::size_t>(k) + 1] += br;
  l.f_z[static_cast<std::size_t>(k)] += f.z - bz;
  l.f_z[static_cast<std::size_t>(k) + 1] += bz;
  l.resultant += f;
  l.axial += f.z;
  l.radial += f_r;
  l.torque_z += rho * f_theta;
  l.circumferential += std::abs(f_theta);
  ++l.contacts;
}

RingLoads wall_ring_loads(const dem::DemSystem& sys, int slot, const dem::WallProfile& profile, bool plane) {
  RingLoads l(profile.station.size());
  const auto& x = sys.particles().x;
  sys.for_each_wall_force(slot, [&](int i, const dem::Vec3& f_grain) {
    const dem::Vec3& xi = x[static_cast<std::size_t>(i)];
    add_contact(l, profile, plane ? std::hypot(xi.x, xi.y) : xi.z, xi, -1.0 * f_grain);
  });
  return l;
}

double surface_node_dt(const dem::WallLaw& law, const fe::Nodes& nodes, const std::vector<int>& surface,
                       const std::vector<double>& areas, double r_min) {
  const double grain_area = std::numbers::pi * r_min * r_min;
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < surface.size(); ++a) {
    // Grains touching a wall in one layer have centres >= 2 r_min apart: at most
    // A / (2 sqrt(3) r_min^2) < A / (pi r_min^2) of them on a node's tributary area A.
    const double mass = nodes.mass[static_cast<std::size_t>(surface[a])] / std::max(1.0, areas[a] / grain_area);
    dt = std::min(dt, std::visit(
                          [&](const auto& l) -> double {
                            if constexpr (std::is_same_v<std::decay_t<decltype(l)>, dem::LinearSpring>) {
                              return l.stable_dt(mass);
                            } else {
                              throw InputError("", "specimen.wall_normal_stiffness",
                                               "the FE-DEM coupling needs a linear grain-wall law");
                            }
                          },
                          law));
  }
  return dt;
}

}  // namespace kolsky::coupling
