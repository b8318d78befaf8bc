// `kolsky eos --water W [--porosity N] [--eps-max E] [--points K] [--k-p MPA] [--e-o MPA]
//             [--stepper NAME] [--abs-tol A] [--rel-tol R] [-o OUT.csv]`
// The three-phase EOS of Sec. 2.3.6 (Eqs. 2.1-2.9, docs/eos.md): P(eps_v) with its branches
// P_BC, P_D, P_E written as CSV, with comment lines recording the model inputs, the K_p/E_o used
// and the ODE stepper and tolerances. W is the gravimetric water content in percent (0-25),
// as the dissertation quotes it ("3 %"); a trailing '%' is accepted.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "core/errors.hpp"
#include "eos/eos_curve.hpp"
#include "eos/moisture_law.hpp"
#include "io/csv.hpp"

namespace kolsky::app {
namespace {

constexpr const char* kWho = "kolsky eos";

struct EosOptions {
  std::optional<double> water_percent;  // required
  double porosity = 0.45;       // Sec. 2.2
  double eps_max = 0.15;        // covers the 10-20 MPa calibration range at 3-20 %
  int points = 151;
  std::optional<double> k_p_mpa;  // unset: from the moisture law
  std::optional<double> e_o_mpa;
  eos::OdeSettings ode;         // dopri5, abs/rel 1e-10 unless given
  std::string output = "eos.csv";
  std::string command_line = "kolsky eos";
};

double parse_number(const std::string& option, std::string text) {
  if (option == "--water" && !text.empty() && text.back() == '%') text.pop_back();
  double v = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, v);
  if (text.empty() || ec != std::errc() || ptr != last)
    throw InputError(kWho, option, "must be a number, got '" + text + "'");
  return v;
}

void require(bool ok, const std::string& option, const std::string& rule) {
  if (!ok) throw InputError(kWho, option, rule);
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

EosOptions parse(const std::vector<std::string>& args) {
  EosOptions o;
  for (const auto& a : args) o.command_line += " " + a;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.empty() || a[0] != '-') throw UsageError("unexpected argument '" + a + "'");
    static const std::vector<std::string> known{"--water", "--porosity", "--eps-max", "--points",
                                                "--k-p", "--e-o", "--stepper", "--abs-tol",
                                                "--rel-tol", "-o"};
    bool ok = false;
    for (const auto& k : known) ok = ok || a == k;
    if (!ok) throw UsageError("unknown option '" + a + "'");
    if (i + 1 >= args.size()) throw UsageError("option '" + a + "' needs a value");
    const std::string& v = args[++i];
    if (a == "-o") o.output = v;
    else if (a == "--stepper") {
      try {
        o.ode.stepper = eos::stepper_from_name(v);
      } catch (const std::invalid_argument& e) {
        throw InputError(kWho, a, e.what());
      }
    } else {
      const double x = parse_number(a, v);
      if (a == "--water") o.water_percent = x;
      else if (a == "--porosity") o.porosity = x;
      else if (a == "--eps-max") o.eps_max = x;
      else if (a == "--k-p") o.k_p_mpa = x;
      else if (a == "--e-o") o.e_o_mpa = x;
      else if (a == "--abs-tol") o.ode.abs_tol = x;
      else if (a == "--rel-tol") o.ode.rel_tol = x;
      else {
        require(x >= 2 && x <= 100000 && x == std::floor(x), a,
                "must be a whole number in [2, 100000]");
        o.points = static_cast<int>(x);
      }
    }
  }
  if (!o.water_percent)
    throw UsageError("needs --water W (gravimetric water content in percent, 0-25)");
  require(*o.water_percent >= 0.0 && *o.water_percent <= 25.0, "--water",
          "must lie in [0, 25] percent (gravimetric), got " + num(*o.water_percent));
  require(o.porosity > 0.0 && o.porosity < 1.0, "--porosity",
          "must lie in (0, 1), got " + num(o.porosity));
  require(o.eps_max > 0.0 && o.eps_max < o.porosity, "--eps-max",
          "must lie in (0, porosity = " + num(o.porosity) + "), got " + num(o.eps_max));
  for (auto [name, v] : {std::pair{"--abs-tol", o.ode.abs_tol}, std::pair{"--rel-tol", o.ode.rel_tol}})
    require(v >= 1e-14 && v <= 1e-3, name, "must lie in [1e-14, 1e-3], got " + num(v));
  for (auto [name, v] : {std::pair{"--k-p", o.k_p_mpa}, std::pair{"--e-o", o.e_o_mpa}})
    require(!v || (*v >= 0.0 && *v <= 1e5), name, "must lie in [0, 1e5] MPa, got " + num(v.value_or(0.0)));
  return o;
}

}  // namespace

int cmd_eos(const std::vector<std::string>& args) {
  const EosOptions o = parse(args);

  eos::ThreePhaseParams base;
  base.porosity = o.porosity;
  const double w = *o.water_percent / 100.0;
  const double w_sat = eos::saturation_water_content(o.porosity, base.solid.rho0, base.water.rho0);
  require(w <= w_sat, "--water",
          "exceeds saturation at porosity " + num(o.porosity) + " (" + num(100.0 * w_sat) + " %)");
  // The K_p/E_o law was calibrated on the n = 0.45 specimens; it is not rescaled with --porosity.
  eos::ThreePhaseParams p = eos::params_at_water_content(eos::dissertation_moisture_law(), base, w);
  if (o.k_p_mpa) p.k_p = *o.k_p_mpa * 1e6;
  if (o.e_o_mpa) p.e_o = *o.e_o_mpa * 1e6;

  const eos::ThreePhaseModel m(p);
  const eos::EosCurve c =
      eos::solve_eos(m, eos::uniform_strains(o.eps_max, static_cast<std::size_t>(o.points)), o.ode);

  io::CsvTable t;
  t.header = {"eps_v", "p_pa", "p_bc_pa", "p_d_pa", "p_e_pa", "tangent_modulus_pa", "void_closure"};
  t.columns = {c.eps_v, c.p, c.p_bc, c.p_d, c.p_e, c.tangent, c.closure};
  const eos::PhaseVolumes& v = m.initial();
  const std::string law = "from the moisture law of docs/eos.md";
  const std::string comment =
      o.command_line +
      "\nthree-phase EOS (Henrych 1979, Wang et al. 2004; dissertation Sec. 2.3.6, Eqs. 2.1-2.9);"
      " see docs/eos.md" +
      "\nwater content w = " + num(*o.water_percent) + " % (gravimetric), porosity n = " +
      num(o.porosity) + "; initial volumes per unit volume: solid " + num(v.solid) + ", water " +
      num(v.water) + ", air " + num(v.air) +
      "\nK_p = " + num(p.k_p / 1e6) + " MPa (" + (o.k_p_mpa ? "--k-p" : law) + "), E_o = " +
      num(p.e_o / 1e6) + " MPa (" + (o.e_o_mpa ? "--e-o" : law) + "), f = " + num(p.friction) +
      ", B = " + num(p.b) + "; K_p and E_o are MPa per unit volume fraction (V0 = 1)" +
      "\nphases: water rho " + num(p.water.rho0) + " kg/m3, c " + num(p.water.c0) + " m/s, k " +
      num(p.water.k) + "; solid rho " + num(p.solid.rho0) + " kg/m3, c " + num(p.solid.c0) +
      " m/s, k " + num(p.solid.k) + "; air P_ao " + num(p.air.p0) + " Pa, rho " +
      num(p.air.rho0) + " kg/m3, k " + num(p.air.k) +
      "\nODE: Boost.Odeint controlled " + eos::stepper_name(c.ode.stepper) + ", abs_tol " +
      num(c.ode.abs_tol) + ", rel_tol " + num(c.ode.rel_tol) +
      " on the state {P / 1 MPa, s, P_BC / 1 MPa}; " + std::to_string(c.stats.n_steps) +
      " steps, " + std::to_string(c.stats.n_rhs) + " right-hand-side evaluations" +
      "\neps_v = 1 - V/V0 (compression positive); pressures are gauge, Pa above the initial "
      "ambient " + num(p.air.p0) + " Pa; p = p_bc + p_d + p_e (Eq. 2.1); void_closure s = -dV_p";
  io::write_csv(o.output, t, comment);

  std::printf("kolsky eos: w = %s %%, n = %s -> %s (%d points; K_p %s MPa, E_o %s MPa; "
              "K(0) = %s MPa, P(%s) = %s MPa)\n",
              num(*o.water_percent).c_str(), num(o.porosity).c_str(), o.output.c_str(), o.points,
              num(p.k_p / 1e6).c_str(), num(p.e_o / 1e6).c_str(), num(c.tangent.front() / 1e6).c_str(),
              num(o.eps_max).c_str(), num(c.p.back() / 1e6).c_str());
  if (o.eps_max > v.air)
    std::fprintf(stderr,
                 "kolsky eos: warning: eps_v passes the air volume %s: the air is expelled and the "
                 "water locks up (Sec. 2.3.5 assumes it never is)\n",
                 num(v.air).c_str());
  return 0;
}

}  // namespace kolsky::app
