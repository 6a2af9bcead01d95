/* Special functions the Hyper-Cauchy masking term needs. */
#ifndef BRDF_SPECIAL_FUNCTIONS_H
#define BRDF_SPECIAL_FUNCTIONS_H
#include "single_source/vocabulary.h"

/* Continued fraction of the incomplete beta function, evaluated with the modified Lentz method
 * (DLMF 8.17.22); converges fast for x < (a + 1) / (a + b + 2). */
SS_FN float incomplete_beta_fraction(float a, float b, float x) {
    const float tiny = 1e-30f;
    float c = 1.0f;
    float d = 1.0f - (a + b) * x / (a + 1.0f);
    d = 1.0f / (fabs(d) < tiny ? tiny : d);
    float h = d;
    for (int m = 1; m <= 100; ++m) {
        float fm = (float)m;
        /* even step d_{2m} */
        float num = fm * (b - fm) * x / ((a + 2.0f * fm - 1.0f) * (a + 2.0f * fm));
        d = 1.0f + num * d;
        d = 1.0f / (fabs(d) < tiny ? tiny : d);
        c = 1.0f + num / c;
        c = fabs(c) < tiny ? tiny : c;
        h *= d * c;
        /* odd step d_{2m+1} */
        num = -(a + fm) * (a + b + fm) * x / ((a + 2.0f * fm) * (a + 2.0f * fm + 1.0f));
        d = 1.0f + num * d;
        d = 1.0f / (fabs(d) < tiny ? tiny : d);
        c = 1.0f + num / c;
        c = fabs(c) < tiny ? tiny : c;
        float delta = d * c;
        h *= delta;
        if (fabs(delta - 1.0f) < 3e-7f) break;
    }
    return h;
}

/* log(1 / B(a, b)), the normalising constant of I_x(a, b): hoisted out of loops that evaluate I many
 * times with the same a and b. */
SS_FN float incomplete_beta_log_norm(float a, float b) { return lgamma(a + b) - lgamma(a) - lgamma(b); }

/* Regularised incomplete beta function I_x(a, b), a, b > 0, x in [0, 1], given incomplete_beta_log_norm(a, b). */
SS_FN float incomplete_beta_normed(float a, float b, float x, float log_norm) {
    if (x <= 0.0f) return 0.0f;
    if (x >= 1.0f) return 1.0f;
    float front = exp(log_norm + a * log(x) + b * log(1.0f - x));
    if (x < (a + 1.0f) / (a + b + 2.0f)) return front * incomplete_beta_fraction(a, b, x) / a;
    /* symmetry I_x(a, b) = 1 - I_{1-x}(b, a) keeps the fraction in its fast region */
    return 1.0f - front * incomplete_beta_fraction(b, a, 1.0f - x) / b;
}

SS_FN float incomplete_beta(float a, float b, float x) {
    return incomplete_beta_normed(a, b, x, incomplete_beta_log_norm(a, b));
}

#endif
