// The chi-square distribution's upper tail, through the regularised incomplete gamma function,
// and the Sidak-corrected significance level of one test among many.
#pragma once

namespace lab::validation {

// Regularised lower and upper incomplete gamma, P(a, x) + Q(a, x) = 1, for a > 0, x >= 0.
double regularized_gamma_p(double a, double x);
double regularized_gamma_q(double a, double x);

// Probability that a chi-square variable with `dof` degrees of freedom exceeds `statistic`.
double chi_square_survival(double statistic, double dof);

// Per-test level that keeps the family-wise error of `tests` independent tests at `significance`.
double sidak_alpha(double significance, int tests);

}  // namespace lab::validation
