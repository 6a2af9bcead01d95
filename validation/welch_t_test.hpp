// Welch's t-test: are two sets of independent estimates of the same quantity, with unknown and
// unequal variances, consistent with equal means? Two renderers (BDPT and the path tracer, or two
// light-sampling strategies) estimate the same image; their per-region means over independent
// renders (other seeds) are compared region by region, with no converged reference (Jung et al.,
// "Detecting bias in Monte Carlo renderers using Welch's t-test", JCGT 9(2), 2020).
#pragma once

#include <vector>

namespace lab::validation {

// The regularised incomplete beta function I_x(a, b), for a, b > 0 and x in [0, 1].
double regularized_beta(double a, double b, double x);

// P(|T| >= |t|) for Student's t with `dof` > 0 degrees of freedom (fractional dof allowed).
double student_t_two_sided(double t, double dof);

// The critical value of a two-sided test at `level` in (0, 1): the t >= 0 with
// student_t_two_sided(t, dof) = level (to a relative 1e-10).
double student_t_critical(double level, double dof);

struct WelchResult {
    double mean_a = 0.0, mean_b = 0.0;
    double standard_error = 0.0;  // of mean_a - mean_b: sqrt(var_a / n_a + var_b / n_b)
    double t = 0.0;               // (mean_a - mean_b) / standard_error
    double dof = 0.0;             // Welch-Satterthwaite
    double p_value = 1.0;         // two-sided; 1 when both sets have zero variance and equal means
};

// Needs at least two values in each set. Equal sets of constants give p = 1; constants that differ
// give p = 0.
WelchResult welch_t_test(const std::vector<double>& a, const std::vector<double>& b);

// Student's paired t-test: a[i] and b[i] are one pair of estimates (two renderers given the same
// random numbers, so their noise is partly shared), the pairs independent of each other. The
// one-sample t-test of the differences a[i] - b[i] (dof n - 1): the shared noise cancels in them.
// Fills the same fields; needs as many values in each set, at least two.
WelchResult paired_t_test(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace lab::validation
