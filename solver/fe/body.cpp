#include "fe/body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"
#include "fe/quad_axisym.hpp"

namespace kolsky::fe {

namespace {

// One element: stress update from the displacement increment, then the internal force at t^n.
// Returns false when the element is inverted in the mid-step or current configuration.
template <class M>
bool update_element(const M& mat, const YieldLine& yield, const Mesh& mesh, int e, ElementState& st) {
  const auto& nd = mesh.nodes;
  const auto& q = mesh.quads[static_cast<std::size_t>(e)];
  Quad4 r, z, dur, duz, rm, zm;
  for (int a = 0; a < 4; ++a) {
    const auto i = static_cast<std::size_t>(q[a]);
    r[a] = nd.r(i);
    z[a] = nd.z(i);
    dur[a] = nd.ur[i] - nd.ur_prev[i];
    duz[a] = nd.uz[i] - nd.uz_prev[i];
    rm[a] = r[a] - 0.5 * dur[a];
    zm[a] = z[a] - 0.5 * duz[a];
  }
  const QuadGeometry gm = quad_geometry(rm, zm);
  const QuadGeometry gn = quad_geometry(r, z);
  if (!gm.valid || !gn.valid) return false;
  const auto ue = static_cast<std::size_t>(e);

  // Pressure from the total volume ratio: no drift from summed increments.
  const double p_old = st.pressure[ue];
  const double eps_v = 1.0 - gn.volume / st.volume0[ue];
  const double p = update_pressure(mat, eps_v, st.eps_max[ue]);
  // Trapezoid rule of -p dV: exact along each linear segment of the EOS.
  double dwork = -0.5 * (p_old + p) * (gn.volume - st.volume[ue]);

  const double g2 = 2.0 * shear_modulus(mat);
  const double cap = yield.at(p);
  double* dev = &st.deviator[16 * ue];
  for (int g = 0; g < kGaussPoints; ++g) {
    double de[4] = {0, 0, 0, 0}, spin = 0.0;
    for (int a = 0; a < 4; ++a) {
      de[0] += gm.dn_dr[g][a] * dur[a];
      de[1] += gm.dn_dz[g][a] * duz[a];
      de[2] += gm.n_over_r[g][a] * dur[a];
      de[3] += gm.dn_dz[g][a] * dur[a] + gm.dn_dr[g][a] * duz[a];
      spin += 0.5 * (gm.dn_dz[g][a] * dur[a] - gm.dn_dr[g][a] * duz[a]);
    }
    double* sg = dev + 4 * g;
    const Deviator s_old = {sg[0], sg[1], sg[2], sg[3]};
    // Jaumann rotation of the old deviator by the r-z spin (hoop direction is a principal one).
    Deviator s = {s_old[0] + 2.0 * spin * s_old[3], s_old[1] - 2.0 * spin * s_old[3], s_old[2],
                  s_old[3] + spin * (s_old[1] - s_old[0])};
    const double tr3 = (de[0] + de[1] + de[2]) / 3.0;
    s[0] += g2 * (de[0] - tr3);
    s[1] += g2 * (de[1] - tr3);
    s[2] += g2 * (de[2] - tr3);
    s[3] += 0.5 * g2 * de[3];
    limit_deviator(s, cap);
    for (int c = 0; c < 4; ++c) sg[c] = s[c];
    // Deviatoric work, trapezoid in stress on the mid-step volume (s is traceless, so s:de
    // only sees the deviatoric strain).
    double w = 0.0;
    for (int c = 0; c < 4; ++c) w += 0.5 * (s_old[c] + s[c]) * de[c];
    dwork += gm.weight[g] * w;
  }

  // f_a = sum_g w_g B_g^T s_g - p dV/dx_a (B-bar: the pressure acts through the element volume).
  double* f = &st.force[8 * ue];
  for (int a = 0; a < 4; ++a) {
    double fr = -p * gn.dvol_dr[a], fz = -p * gn.dvol_dz[a];
    for (int g = 0; g < kGaussPoints; ++g) {
      const double* sg = dev + 4 * g;
      fr += gn.weight[g] * (gn.dn_dr[g][a] * sg[0] + gn.dn_dz[g][a] * sg[3] + gn.n_over_r[g][a] * sg[2]);
      fz += gn.weight[g] * (gn.dn_dz[g][a] * sg[1] + gn.dn_dr[g][a] * sg[3]);
    }
    f[2 * a] = fr;
    f[2 * a + 1] = fz;
  }
  st.pressure[ue] = p;
  st.volume[ue] = gn.volume;
  st.work[ue] += dwork;
  st.courant[ue] = courant_length(r, z);
  return true;
}

}  // namespace

Body::Body(Mesh mesh, std::vector<Part> parts, int threads)
    : mesh_(std::move(mesh)), parts_(std::move(parts)), threads_(threads) {
  if (threads_ < 1) throw InputError("", "fe.threads", "must be >= 1");
  const std::size_t n_el = mesh_.quads.size();
  int covered = 0;
  for (const auto& p : parts_) {
    if (p.first_element != covered || p.n_elements < 1)
      throw InputError("", "fe.parts", "parts must cover the elements in order, without gaps");
    covered += p.n_elements;
    std::visit([](const auto& m) { m.validate("fe.material"); }, p.material);
    part_wave_speed_.push_back(max_wave_speed(p.material));
  }
  if (static_cast<std::size_t>(covered) != n_el)
    throw InputError("", "fe.parts", "parts must cover every element");
  mesh_.build_incidence();
  state_.volume0.assign(n_el, 0.0);
  state_.pressure.assign(n_el, 0.0);
  state_.eps_max.assign(n_el, 0.0);
  state_.deviator.assign(16 * n_el, 0.0);
  state_.work.assign(n_el, 0.0);
  state_.force.assign(8 * n_el, 0.0);
  state_.courant.assign(n_el, 0.0);
  const auto& shape = gauss_shape_functions();
  for (const auto& p : parts_) {
    const double rho = std::visit([](const auto& m) { return density(m); }, p.material);
    for (int e = p.first_element; e < p.first_element + p.n_elements; ++e) {
      Quad4 r, z;
      current_coordinates(mesh_, e, r, z);
      const QuadGeometry g = quad_geometry(r, z);
      if (!g.valid) throw InputError("", "fe.mesh", "element " + std::to_string(e) + " is inverted");
      state_.volume0[static_cast<std::size_t>(e)] = g.volume;
      state_.courant[static_cast<std::size_t>(e)] = courant_length(r, z);
      // Row-sum lumping: m_a = rho * integral of N_a over the ring; positive for every node,
      // including those on the axis.
      for (int a = 0; a < 4; ++a) {
        double m = 0.0;
        for (int gp = 0; gp < kGaussPoints; ++gp) m += rho * g.weight[gp] * shape[gp][a];
        mesh_.nodes.mass[static_cast<std::size_t>(mesh_.quads[static_cast<std::size_t>(e)][a])] += m;
      }
    }
  }
  state_.volume = state_.volume0;
}

void Body::update_internal_forces() {
  int inverted = 0;
  for (const auto& part : parts_) {
    const int lo = part.first_element, hi = part.first_element + part.n_elements;
    std::visit(
        [&](const auto& mat) {
          const YieldLine yield = yield_line(mat);
#pragma omp parallel for schedule(static) reduction(| : inverted) num_threads(threads_) if (threads_ > 1)
          for (int e = lo; e < hi; ++e) inverted |= update_element(mat, yield, mesh_, e, state_) ? 0 : 1;
        },
        part.material);
  }
  if (inverted) throw NumericalError("fe: an element inverted (det J <= 0)", time_);
  auto& nd = mesh_.nodes;
  const int n = static_cast<int>(nd.size());
  const auto& inc = mesh_.incidence;
  const auto& start = mesh_.incidence_start;
#pragma omp parallel for schedule(static) num_threads(threads_) if (threads_ > 1)
  for (int i = 0; i < n; ++i) {
    double fr = 0.0, fz = 0.0;
    for (int k = start[static_cast<std::size_t>(i)]; k < start[static_cast<std::size_t>(i) + 1]; ++k) {
      const auto slot = static_cast<std::size_t>(2 * inc[static_cast<std::size_t>(k)]);
      fr += state_.force[slot];
      fz += state_.force[slot + 1];
    }
    nd.fr_int[static_cast<std::size_t>(i)] = fr;
    nd.fz_int[static_cast<std::size_t>(i)] = fz;
  }
}

void Body::advance(double dt, double mass_damping) {
  auto& nd = mesh_.nodes;
  const double dt_avg = started_ ? 0.5 * (dt_prev_ + dt) : 0.5 * dt;
  const double h = 0.5 * mass_damping * dt_avg;
  double ke = 0.0, damped = 0.0;
  auto update = [&](double m, double f, bool fixed, double& v, double& u, double& u_prev) {
    const double v_old = v;
    // (1 + h) v_new = (1 - h) v_old + dt_avg f/m: damping taken at the mid-step velocity.
    const double v_new = fixed ? 0.0 : ((1.0 - h) * v_old + dt_avg * f / m) / (1.0 + h);
    // Kinetic energy at t^n as m v^{n-1/2} v^{n+1/2} / 2: with it, kinetic energy plus the
    // trapezoid work of the nodal forces is exactly conserved by central differences for a
    // linear system (Hughes 1987, Sec. 9.3), and stays positive only below the critical dt.
    // The first step mirrors v^{1/2} about v^0 for the missing v^{-1/2}.
    const double v_before = started_ ? v_old : 2.0 * v_old - v_new;
    const double v_mid = 0.5 * (v_old + v_new);
    ke += 0.5 * m * v_before * v_new;
    damped += mass_damping * m * v_mid * v_mid * dt_avg;
    v = v_new;
    u_prev = u;
    u += dt * v_new;
  };
  // Serial: the sums must not depend on the thread count, and this loop is O(nodes).
  for (std::size_t i = 0; i < nd.size(); ++i) {
    update(nd.mass[i], nd.fr_ext[i] - nd.fr_int[i], nd.fixed_r[i], nd.vr[i], nd.ur[i], nd.ur_prev[i]);
    update(nd.mass[i], nd.fz_ext[i] - nd.fz_int[i], nd.fixed_z[i], nd.vz[i], nd.uz[i], nd.uz_prev[i]);
  }
  kinetic_ = ke;
  damping_work_ += damped;
  dt_prev_ = dt;
  started_ = true;
  time_ += dt;
}

double Body::material_work() const {
  double w = 0.0;
  for (double x : state_.work) w += x;
  return w;
}

double Body::elastic_energy() const {
  double u = 0.0;
  for (const auto& part : parts_) {
    const auto* el = std::get_if<LinearElastic>(&part.material);
    if (!el) continue;
    const double g = el->shear_modulus(), k = el->bulk_modulus();
    for (int e = part.first_element; e < part.first_element + part.n_elements; ++e) {
      Quad4 r, z;
      current_coordinates(mesh_, e, r, z);
      const QuadGeometry geo = quad_geometry(r, z);
      const auto ue = static_cast<std::size_t>(e);
      const double* s = &state_.deviator[16 * ue];
      for (int gp = 0; gp < kGaussPoints; ++gp) {
        const double* sg = s + 4 * gp;
        const double ss = sg[0] * sg[0] + sg[1] * sg[1] + sg[2] * sg[2] + 2.0 * sg[3] * sg[3];
        u += geo.weight[gp] * ss / (4.0 * g);
      }
      u += state_.pressure[ue] * state_.pressure[ue] * geo.volume / (2.0 * k);
    }
  }
  return u;
}

double Body::stable_dt() const {
  // 0.9: on rectangles the exact limit (Lanczos) is h_min/c times 0.915 (square, nu -> 0.5:
  // the mean-dilatation volumetric mode) to 1.0; distorted meshes sit higher (docs/fe.md).
  constexpr double kMeanDilatationMargin = 0.9;
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const auto& part = parts_[k];
    for (int e = part.first_element; e < part.first_element + part.n_elements; ++e)
      dt = std::min(dt, kMeanDilatationMargin * std::max(0.0, state_.courant[static_cast<std::size_t>(e)]) /
                            part_wave_speed_[k]);
  }
  return dt;
}

double Body::axial_stress(int e) const {
  Quad4 r, z;
  current_coordinates(mesh_, e, r, z);
  const QuadGeometry geo = quad_geometry(r, z);
  const auto ue = static_cast<std::size_t>(e);
  double s = 0.0;
  for (int gp = 0; gp < kGaussPoints; ++gp) s += geo.weight[gp] * state_.deviator[16 * ue + 4 * gp + 1];
  return s / geo.volume - state_.pressure[ue];
}

bool Body::finite() const {
  const auto& nd = mesh_.nodes;
  for (std::size_t i = 0; i < nd.size(); ++i)
    if (!std::isfinite(nd.ur[i]) || !std::isfinite(nd.uz[i]) || !std::isfinite(nd.vr[i]) ||
        !std::isfinite(nd.vz[i]))
      return false;
  for (double p : state_.pressure)
    if (!std::isfinite(p)) return false;
  return true;
}

}  // namespace kolsky::fe
