/* Anisotropic Hyper-Cauchy distribution of normals (Butler et al. 2015, "Experimental and
 * theoretical basis for a closed-form spectral BRDF model"), made anisotropic by stretching slope
 * space like GGX. With slope r^2 = x^2/sx^2 + y^2/sy^2 (unit-width slopes), the slope density is
 *   P22(x, y) = (g - 1) 2^(g - 1) / (pi sx sy) (2 + r^2)^(-g),   D(m) = P22 / cos^4 theta_m,
 * width s > 0, shape g > 1. For g = 2 it is GGX with alpha = sqrt(2) s. */
#ifndef BRDF_HYPER_CAUCHY_H
#define BRDF_HYPER_CAUCHY_H
#include "single_source/vocabulary.h"
#include "special_functions.h"

/* D(m) written in m: cos^4 (2 + tan^2-term)^g = m_z^(4 - 2g) (2 m_z^2 + q)^g, q = (mx/sx)^2 + (my/sy)^2. */
SS_FN float hyper_cauchy_d(float3 m, float sx, float sy, float g) {
    if (m.z <= 0.0f) return 0.0f;
    float q = sqr(m.x / sx) + sqr(m.y / sy);
    float norm = (g - 1.0f) * pow(2.0f, g - 1.0f) / (SS_PI * sx * sy);
    return norm * pow(m.z, 2.0f * g - 4.0f) * pow(2.0f * m.z * m.z + q, -g);
}

/* Smith Lambda from the marginal slope density P2(q) = C (2 + q^2)^(1/2 - g),
 * C = (g - 1) 2^(g - 1) Gamma(g - 1/2) / (sqrt(pi) Gamma(g)). With mu = cot theta / s(phi):
 *   Lambda = (1/mu) int_mu^inf (q - mu) P2(q) dq
 *          = C (2 + mu^2)^(3/2 - g) / (2 mu (g - 3/2)) - I_{2/(2+mu^2)}(g - 1, 1/2) / 2.
 * The tail of P2 is a Student-t tail, hence the incomplete beta. Finite for g > 3/2 only: heavier
 * tails have infinite mean slope and mask everything but normal incidence. */
SS_FN float hyper_cauchy_lambda(float3 w, float sx, float sy, float g) {
    float tangential = sqrt(sqr(sx * w.x) + sqr(sy * w.y));
    float cz = fabs(w.z);
    if (!(tangential > 0.0f)) return 0.0f;
    float mu = cz / tangential;
    if (mu < 1e-12f) return 1e30f;
    if (mu > 1e15f) return 0.0f;
    float mu2 = mu * mu;
    float log_c = log(g - 1.0f) + (g - 1.0f) * log(2.0f) + lgamma(g - 0.5f) - 0.5f * log(SS_PI) - lgamma(g);
    float first = exp(log_c + (1.5f - g) * log(2.0f + mu2)) / (2.0f * mu * (g - 1.5f));
    float tail = 0.5f * incomplete_beta(g - 1.0f, 0.5f, 2.0f / (2.0f + mu2));
    return fmax(first - tail, 0.0f);
}

/* Exact inversion of the distribution of normals D(m) cos theta_m: the unit radial slope w = r^2
 * has CDF 1 - (2 / (2 + w))^(g - 1), so w = 2 ((1 - u)^(-1/(g - 1)) - 1). pdf(m) = D(m) cos theta_m. */
SS_FN float3 hyper_cauchy_sample_normal(float sx, float sy, float g, float u1, float u2) {
    float one_minus_u = fmax(1.0f - u1, 1e-7f);
    float w = 2.0f * (pow(one_minus_u, -1.0f / (g - 1.0f)) - 1.0f);
    float r = safe_sqrt(w);
    float phi = 2.0f * SS_PI * u2;
    float slope_x = sx * r * cos(phi), slope_y = sy * r * sin(phi);
    return normalize(make_float3(-slope_x, -slope_y, 1.0f));
}

#endif
