// Explicit stability limits of an FE body. Central differences are stable for
// dt <= 2/omega_max, omega_max^2 the largest eigenvalue of M^{-1} K (Belytschko, Liu & Moran
// 2000, Sec. 6.3). Two estimates:
//   stable dt (cheap, every step): the element Courant bound min_e L_e/c_e composed with the
//     penalty springs, lambda <= lambda_elements + lambda_springs (eigenvalues of a sum of
//     symmetric positive semi-definite operators), lambda_elements = (2 c / L_e)^2 and
//     lambda_springs a Gershgorin row-sum bound of M^{-1/2} P M^{-1/2};
//   critical dt (Lanczos, verification): omega_max of the linearised body (B-bar stiffness with
//     each part's steepest tangent) plus the contact springs, by Lanczos with full
//     re-orthogonalisation (Golub & Van Loan 2013, Sec. 10.1).
#pragma once
#include <vector>

#include "fe/body.hpp"
#include "fe/contact.hpp"

namespace kolsky::fe {

/// Gershgorin bound on the largest eigenvalue of M^{-1} P for the springs (1/s^2); fixed
/// degrees of freedom are skipped.
double spring_eigen_bound(const Nodes& nodes, const std::vector<SpringStencil>& springs);

/// Stable dt of the element bound dt_elements (s) with the springs' eigenvalue bound lambda_s:
/// 2 / sqrt((2/dt_elements)^2 + lambda_s).
double compose_stable_dt(double dt_elements, double spring_bound);

/// Critical dt 2/omega_max of the body linearised about its current configuration, with the
/// springs added, from n_lanczos Lanczos steps (the largest Ritz value; converges from below,
/// so the returned dt converges from above to the exact limit).
double critical_dt(const Body& body, const std::vector<SpringStencil>& springs, int n_lanczos);

}  // namespace kolsky::fe
