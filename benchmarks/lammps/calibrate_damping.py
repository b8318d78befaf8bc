#!/usr/bin/env python3
"""Damping constants of benchmarks/lammps/in.compaction_hertz_history (pure Python, no numpy).

pair_style gran/hertz/history (LAMMPS) uses
    F_n = sqrt(delta R*) (k_n delta - m* gamma_n v_n),   F_t = -sqrt(delta R*) (k_t s + m* gamma_t v_t)
i.e. a Kuwabara-Kono-like dashpot (c ~ sqrt(delta)) whose restitution depends on the impact speed
and the grain size, whereas kolsky (and pair_style granular ... damping tsuji) use the Tsuji
dashpot c = 2 sqrt(5/6) beta sqrt(S_n m*), S_n = 2 E* sqrt(R* delta) (c ~ delta^{1/4}), whose
restitution is the same at all speeds and sizes. No gamma_n reproduces that everywhere, so gamma_n
is chosen so that a head-on impact of the reference pair at the reference speed rebounds with
e = 0.5 (bisection on an RK4 integration of the 1-D impact), separately for grain-grain (two
equal grains) and grain-wall (one grain on a rigid wall). The table printed afterwards shows how
e drifts with size and speed. gamma_t = sqrt(4 G*/E*) gamma_n, the ratio kolsky uses between its
tangential and normal dashpots (c_t = c_n sqrt(k_t / S_n)).

Usage: python3 calibrate_damping.py [d_ref_m] [v_ref_m_per_s]   (defaults 0.4e-3 m, 1.0 m/s)
"""
import math
import sys

E, NU, RHO, E_REST = 78e9, 0.3, 2650.0, 0.5
G = E / (2 * (1 + NU))                                   # 30 GPa
E_PAIR = E / (2 * (1 - NU * NU))                         # E* grain-grain, 42.86 GPa
E_WALL = E / (1 - NU * NU)                               # E* grain-rigid wall, 85.71 GPa
G_PAIR = 1 / (2 * 2 * (2 - NU) * (1 + NU) / E)           # G* grain-grain, 8.82 GPa
G_WALL = 1 / (2 * (2 - NU) * (1 + NU) / E)               # G* grain-rigid wall, 17.65 GPa


def mass(d):
    return RHO * math.pi * d ** 3 / 6


def restitution(force, v0, m, t_scale):
    """RK4 on m x'' = force(x, x'), x(0) = 0, x'(0) = v0; e = -x'(end) / v0."""
    h = t_scale / 20000
    x, v, t = 0.0, v0, 0.0

    def acc(x, v):
        return force(x, v) / m if x > 0 else 0.0

    while t < 50 * t_scale:
        k1x, k1v = v, acc(x, v)
        k2x, k2v = v + 0.5 * h * k1v, acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v)
        k3x, k3v = v + 0.5 * h * k2v, acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v)
        k4x, k4v = v + h * k3v, acc(x + h * k3x, v + h * k3v)
        xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
        t += h
        if xn <= 0:
            s = x / (x - xn)
            return max(0.0, -(v + s * (vn - v)) / v0)
        x, v = xn, vn
    return 0.0


def contact_time(e_star, r_eff, m_eff, v):
    dmax = (15 * m_eff * v * v / (16 * e_star * math.sqrt(r_eff))) ** 0.4
    return 2.94 * dmax / v


def lammps_hertz_history_e(gamma_n, kn, r_eff, m_eff, v):
    def f(x, xd):
        return -math.sqrt(x * r_eff) * (kn * x + m_eff * gamma_n * xd)
    return restitution(f, v, m_eff, contact_time(0.75 * kn, r_eff, m_eff, v))


def calibrate(kn, r_eff, m_eff, v):
    lo, hi = 0.0, 1.0
    while lammps_hertz_history_e(hi, kn, r_eff, m_eff, v) > E_REST:
        hi *= 2
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if lammps_hertz_history_e(mid, kn, r_eff, m_eff, v) > E_REST:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def main():
    d_ref = float(sys.argv[1]) if len(sys.argv) > 1 else 0.4e-3
    v_ref = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
    kn_p, kt_p = 4 / 3 * E_PAIR, 8 * G_PAIR
    kn_w, kt_w = 4 / 3 * E_WALL, 8 * G_WALL
    tang = math.sqrt(4 * G_PAIR / E_PAIR)  # same for the wall (same material ratio)
    m = mass(d_ref)
    g_p = calibrate(kn_p, d_ref / 4, m / 2, v_ref)
    g_w = calibrate(kn_w, d_ref / 2, m, v_ref)
    print(f"reference: d = {d_ref:g} m, v = {v_ref:g} m/s, target e = {E_REST}")
    print(f"grain-grain: kn = {kn_p:.6e} Pa  kt = {kt_p:.6e} Pa  gamma_n = {g_p:.6e} 1/(s m)"
          f"  gamma_t = {tang * g_p:.6e}")
    print(f"grain-wall : kn = {kn_w:.6e} Pa  kt = {kt_w:.6e} Pa  gamma_n = {g_w:.6e} 1/(s m)"
          f"  gamma_t = {tang * g_w:.6e}")
    print("restitution of the calibrated gran/hertz/history pair law (equal grains), by d and v:")
    print("  d (mm)  " + "  ".join(f"v={v:<5g}" for v in (0.1, 0.3, 1.0, 3.0, 9.3)))
    for d in (0.3e-3, 0.4e-3, 0.6e-3, 1.2e-3):
        es = [lammps_hertz_history_e(g_p, kn_p, d / 4, mass(d) / 2, v) for v in (0.1, 0.3, 1.0, 3.0, 9.3)]
        print(f"  {d * 1e3:5.2f}   " + "  ".join(f"{e:7.3f}" for e in es))
    # LAMMPS pair_style granular 'damping tsuji': eta = alpha(e) sqrt(m* (4/3) E* a).
    e = E_REST
    alpha = (1.2728 - 4.2783 * e + 11.087 * e ** 2 - 22.348 * e ** 3 + 27.467 * e ** 4
             - 18.022 * e ** 5 + 4.8218 * e ** 6)
    r, mm = d_ref / 4, m / 2

    def f_tsuji(x, xd):
        k = 4 / 3 * E_PAIR * math.sqrt(r * x)
        return -k * x - alpha * math.sqrt(mm * k) * xd
    beta = -math.log(e) / math.sqrt(math.log(e) ** 2 + math.pi ** 2)

    def f_kolsky(x, xd):
        s = 2 * E_PAIR * math.sqrt(r * x)
        return -4 / 3 * E_PAIR * math.sqrt(r * x) * x - 2 * math.sqrt(5 / 6) * beta * math.sqrt(s * mm) * xd
    tc = contact_time(E_PAIR, r, mm, v_ref)
    print(f"for comparison at the reference impact: granular/tsuji (alpha = {alpha:.4f}) e = "
          f"{restitution(f_tsuji, v_ref, mm, tc):.4f}; kolsky Tsuji (beta = {beta:.4f}) e = "
          f"{restitution(f_kolsky, v_ref, mm, tc):.4f}")


if __name__ == "__main__":
    main()
