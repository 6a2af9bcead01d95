#include "validation/welch_t_test.hpp"

#include <cmath>
#include <stdexcept>

namespace lab::validation {

namespace {

// The continued fraction of I_x(a, b) (Abramowitz and Stegun 26.5.8), evaluated by the modified
// Lentz method; converges fast for x < (a + 1) / (a + b + 2).
double beta_continued_fraction(double a, double b, double x) {
    const double tiny = 1e-300, eps = 1e-15;
    double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
    if (std::fabs(d) < tiny) d = tiny;
    d = 1.0 / d;
    double h = d;
    for (int m = 1; m <= 500; ++m) {
        double m2 = 2.0 * m;
        // even step: d_{2m} = m (b - m) x / ((a + 2m - 1)(a + 2m))
        double numerator = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
        d = 1.0 + numerator * d;
        c = 1.0 + numerator / c;
        if (std::fabs(d) < tiny) d = tiny;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        h *= d * c;
        // odd step: d_{2m+1} = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1))
        numerator = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
        d = 1.0 + numerator * d;
        c = 1.0 + numerator / c;
        if (std::fabs(d) < tiny) d = tiny;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < eps) break;
    }
    return h;
}

double mean_of(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return s / double(v.size());
}

// The unbiased sample variance.
double variance_of(const std::vector<double>& v, double mean) {
    double s = 0.0;
    for (double x : v) s += (x - mean) * (x - mean);
    return s / double(v.size() - 1);
}

}  // namespace

double regularized_beta(double a, double b, double x) {
    if (!(a > 0.0 && b > 0.0 && x >= 0.0 && x <= 1.0)) throw std::invalid_argument("regularized_beta: needs a, b > 0 and x in [0, 1]");
    if (x == 0.0 || x == 1.0) return x;
    // x^a (1 - x)^b / (a B(a, b)), through lgamma
    double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
    if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_continued_fraction(a, b, x) / a;
    return 1.0 - front * beta_continued_fraction(b, a, 1.0 - x) / b;  // I_x(a, b) = 1 - I_{1-x}(b, a)
}

double student_t_two_sided(double t, double dof) {
    if (!(dof > 0.0)) throw std::invalid_argument("student_t_two_sided: dof must be > 0");
    if (std::isinf(t)) return 0.0;
    // P(|T| >= |t|) = I_{dof / (dof + t^2)}(dof / 2, 1 / 2)
    return regularized_beta(0.5 * dof, 0.5, dof / (dof + t * t));
}

double student_t_critical(double level, double dof) {
    if (!(level > 0.0 && level < 1.0)) throw std::invalid_argument("student_t_critical: level must be in (0, 1)");
    // the tail falls from 1 at t = 0: double an upper bound, then bisect
    double lo = 0.0, hi = 1.0;
    while (student_t_two_sided(hi, dof) > level) {
        lo = hi;
        hi *= 2.0;
    }
    while (hi - lo > 1e-10 * hi) {
        double mid = 0.5 * (lo + hi);
        (student_t_two_sided(mid, dof) > level ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

WelchResult welch_t_test(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() < 2 || b.size() < 2) throw std::invalid_argument("welch_t_test: needs at least two values in each set");
    WelchResult r;
    r.mean_a = mean_of(a);
    r.mean_b = mean_of(b);
    double va = variance_of(a, r.mean_a) / double(a.size()), vb = variance_of(b, r.mean_b) / double(b.size());
    double se2 = va + vb;
    r.standard_error = std::sqrt(se2);
    if (se2 == 0.0) {
        r.p_value = r.mean_a == r.mean_b ? 1.0 : 0.0;
        r.t = r.mean_a == r.mean_b ? 0.0 : INFINITY;
        r.dof = double(a.size() + b.size() - 2);
        return r;
    }
    r.t = (r.mean_a - r.mean_b) / r.standard_error;
    r.dof = se2 * se2 / (va * va / double(a.size() - 1) + vb * vb / double(b.size() - 1));
    r.p_value = student_t_two_sided(r.t, r.dof);
    return r;
}

WelchResult paired_t_test(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size() || a.size() < 2) throw std::invalid_argument("paired_t_test: needs as many values in each set, at least two");
    std::vector<double> d(a.size());
    for (size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
    WelchResult r;
    r.mean_a = mean_of(a);
    r.mean_b = mean_of(b);
    double mean_d = mean_of(d);
    r.standard_error = std::sqrt(variance_of(d, mean_d) / double(d.size()));
    r.dof = double(d.size() - 1);
    if (r.standard_error == 0.0) {
        r.p_value = mean_d == 0.0 ? 1.0 : 0.0;
        r.t = mean_d == 0.0 ? 0.0 : INFINITY;
        return r;
    }
    r.t = mean_d / r.standard_error;
    r.p_value = student_t_two_sided(r.t, r.dof);
    return r;
}

}  // namespace lab::validation
