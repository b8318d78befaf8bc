// The calibration search's root-finding sibling (issue 32; log_search.hpp is the minimising
// one): the x where a costly deterministic f(x) crosses zero, each evaluation one simulation
// (Chapter 4's rotational factor against a target modulus, on x = log10(1 - k)). The start
// points are evaluated first (in order, within the cap); the tightest sign change between
// neighbours in x brackets the root; GSL's Brent root finder then runs until |f| is within
// f_tolerance (the objective's own resolution: iterating further chases its noise) or the
// bracket is narrower than x_tolerance. Evaluations are cached by exact x (a simulation never
// runs twice) and capped; evaluations the caller already had (`fresh = false`) are free.
#pragma once
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace kolsky::harness {

struct RootSearchSettings {
  std::vector<double> start_x;  ///< evaluated first, in this order
  double f_tolerance = 0;       ///< stop when |f(x)| <= this
  double x_tolerance = 0;       ///< stop when the Brent bracket is narrower than this
  int max_evaluations = 8;      ///< fresh evaluations at most (start points included)
};

/// One evaluation: f, and whether it ran a simulation (counts against the cap).
struct RootEvaluation {
  double f = NAN;
  bool fresh = true;
};

struct RootSearchResult {
  enum class End { no_bracket, f_tolerance, x_tolerance, budget_spent, non_finite, gsl_error };
  End end = End::no_bracket;
  bool bracketed = false, converged = false;  ///< converged: ended on a tolerance
  double x_lo = NAN, x_hi = NAN;  ///< the start bracket (neighbouring start points, f changes sign)
  double slope = NAN;             ///< df/dx, secant over the start bracket
  double x = NAN;                 ///< the root: Brent's last point, or after a failure the
                                  ///< evaluated point in the start bracket with the smallest |f|
  double final_lo = NAN, final_hi = NAN;  ///< Brent's last bracket
  int iterations = 0, evaluations = 0;    ///< Brent iterations; fresh evaluations
  std::string gsl_message;        ///< End::gsl_error: GSL's reason
  std::vector<std::pair<double, double>> evaluated;  ///< (x, f) in evaluation order
};

/// `objective(x)` is called at most once per distinct x; a non-finite f at a start point
/// leaves that point out of the bracket, inside the Brent phase it ends the search.
RootSearchResult brent_root_search(const std::function<RootEvaluation(double x)>& objective,
                                   const RootSearchSettings& s);

}  // namespace kolsky::harness
