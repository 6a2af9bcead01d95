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

/* A shape's constants, which need lgamma(): a BSDF evaluation computes them once (struct Microfacet)
 * rather than in each Lambda and each sample (seven lgamma per sample, two per Lambda). */
typedef struct HyperCauchyShape {
    float log_norm;         /* log(1 / B(g - 1, 1/2)): the incomplete beta's in Lambda and in the slopes' CDF */
    float log_c;            /* log of the slope densities' constant C = (g - 1) 2^(g - 1) Gamma(g - 1/2) / (sqrt(pi) Gamma(g)) */
    float student_log_norm; /* log(1 / B(nu/2, 1/2)), nu = 2g - 1: the second slope's Student-t CDF */
    float student_k;        /* that Student-t's density at 0, Gamma((nu + 1)/2) / (Gamma(nu/2) sqrt(nu pi)) */
} HyperCauchyShape;

/* Four lgamma for all four: for g in [BRDF_HC_SHAPE_MIN, BRDF_HC_SHAPE_MAX] the arguments
 * (g - 1) + 1/2 = nu/2 = g - 1/2 and (nu + 1)/2 = g are exact in float, so each constant has the
 * bits of its own formula, incomplete_beta_log_norm(g - 1, 1/2) and so on. */
SS_FN HyperCauchyShape hyper_cauchy_shape(float g) {
    float lgamma_g = lgamma(g), lgamma_half_less = lgamma(g - 0.5f), lgamma_half = lgamma(0.5f);
    float nu = 2.0f * g - 1.0f;
    HyperCauchyShape s;
    s.log_norm = lgamma_half_less - lgamma(g - 1.0f) - lgamma_half;
    s.log_c = log(g - 1.0f) + (g - 1.0f) * log(2.0f) + lgamma_half_less - 0.5f * log(SS_PI) - lgamma_g;
    s.student_log_norm = lgamma_g - lgamma_half_less - lgamma_half;
    s.student_k = exp(lgamma_g - lgamma_half_less) / sqrt(nu * SS_PI);
    return s;
}

/* Smith Lambda from the marginal slope density P2(q) = C (2 + q^2)^(1/2 - g). With mu = cot theta / s(phi):
 *   Lambda = (1/mu) int_mu^inf (q - mu) P2(q) dq
 *          = C (2 + mu^2)^(3/2 - g) / (2 mu (g - 3/2)) - I_{2/(2+mu^2)}(g - 1, 1/2) / 2.
 * The tail of P2 is a Student-t tail, hence the incomplete beta. Finite for g > 3/2 only: heavier
 * tails have infinite mean slope and mask everything but normal incidence. shape = hyper_cauchy_shape(g). */
SS_FN float hyper_cauchy_lambda(float3 w, float sx, float sy, float g, HyperCauchyShape shape) {
    float tangential = sqrt(sqr(sx * w.x) + sqr(sy * w.y));
    float cz = fabs(w.z);
    if (!(tangential > 0.0f)) return 0.0f;
    float mu = cz / tangential;
    if (mu < 1e-12f) return 1e30f;
    if (mu > 1e15f) return 0.0f;
    float mu2 = mu * mu;
    float first = exp(shape.log_c + (1.5f - g) * log(2.0f + mu2)) / (2.0f * mu * (g - 1.5f));
    float tail = 0.5f * incomplete_beta_normed(g - 1.0f, 0.5f, 2.0f / (2.0f + mu2), shape.log_norm);
    return fmax(first - tail, 0.0f);
}

/* CDF of a unit slope x of the marginal P2 (a Student-t with 2g - 2 degrees of freedom, x^2 / 2 = t^2 / nu);
 * log_norm = hyper_cauchy_shape(g).log_norm. */
SS_FN float hyper_cauchy_slope_cdf(float x, float g, float log_norm) {
    float tail = 0.5f * incomplete_beta_normed(g - 1.0f, 0.5f, 2.0f / (2.0f + x * x), log_norm);
    return x <= 0.0f ? tail : 1.0f - tail;
}

/* Visible slopes, unit width, wo in the xz-plane with cot theta_o = mu (Heitz and d'Eon 2014): the
 * slope x along wo has density (mu - x) P2(x) / (mu (1 + Lambda)) for x < mu, whose integral from
 * -inf is A(x) / (mu (1 + Lambda)) with
 *   A(x) = mu CDF(x) + C (2 + x^2)^(3/2 - g) / (2g - 3)     (int t P2(t) dt = -C (2+t^2)^(3/2-g) / (2g-3)).
 * Given x, the slope y has density P22(x, y) / P2(x), proportional to (2 + x^2 + y^2)^(-g): a Student-t
 * with nu = 2g - 1, y = sqrt((2 + x^2) / nu) t. Neither CDF has a closed-form inverse; both are inverted
 * by Newton's method on their densities, safeguarded by bisection on a bracket, to float precision,
 * so the normals follow D_wo and the pdf is its closed form. */
#define HYPER_CAUCHY_INVERSION_STEPS 40

/* Both inversions run Newton's method on log CDF against v = asinh(x): in the power-law tails of these
 * densities log CDF is nearly linear in v, so a handful of steps reach float precision even for the
 * heaviest tail (shape 1.6). Each keeps the root bracketed in (lo, hi]; lo = -inf until a point left
 * of the root is found. */
SS_FN float hyper_cauchy_asinh(float x) {
    float r = log(fabs(x) + sqrt(x * x + 1.0f));
    return x < 0.0f ? -r : r;
}
SS_FN float hyper_cauchy_sinh(float v) { float e = exp(v); return 0.5f * (e - 1.0f / e); }

/* v = -40 is a slope of -1.2e17: its square still fits a float, and a normal that steep is horizontal
 * to float precision, so the mass beyond (2.5e-4 of it at shape 1.6) lands where it belongs. */
#define HYPER_CAUCHY_LOWEST_V -40.0f

/* The next iterate: Newton's where it stays inside the bracket, else bisection, or a step twice as far
 * left while the bracket is open. */
SS_FN float hyper_cauchy_next_iterate(float newton, float lo, float hi) {
    if (newton > lo && newton < hi) return fmax(newton, HYPER_CAUCHY_LOWEST_V);
    if (lo < -1e30f) return fmax(fmin(2.0f * hi, hi - 1.0f), HYPER_CAUCHY_LOWEST_V);
    return 0.5f * (lo + hi);
}

SS_FN float hyper_cauchy_sample_visible_slope_x(float mu, float g, HyperCauchyShape shape, float u) {
    /* A scaled by (2g - 3) / C: the power term carries no special function, so at grazing incidence,
     * where it dominates, the root is as precise as pow() and not as the incomplete beta. For u > 1/2
     * the mass above x, A(mu) - A(x), is matched instead: near mu, where the density vanishes, its
     * logarithm still has a slope, and log A has none. */
    float log_norm = shape.log_norm;
    float weight = mu * (2.0f * g - 3.0f) / exp(shape.log_c);
    float cdf_mu = hyper_cauchy_slope_cdf(mu, g, log_norm), power_mu = pow(2.0f + mu * mu, 1.5f - g);
    bool upper = u > 0.5f;
    float log_target = log((upper ? 1.0f - u : u) * (weight * cdf_mu + power_mu));
    float lo = -INFINITY, hi = hyper_cauchy_asinh(mu);
    float v = fmin(0.0f, hi - 1.0f);
    for (int k = 0; k < HYPER_CAUCHY_INVERSION_STEPS; ++k) {
        float x = hyper_cauchy_sinh(v);
        float power = pow(2.0f + x * x, 0.5f - g);
        float cdf = hyper_cauchy_slope_cdf(x, g, log_norm);
        float mass = upper ? weight * (cdf_mu - cdf) + (power_mu - power * (2.0f + x * x)) : weight * cdf + power * (2.0f + x * x);
        /* increasing in v either way; d log(mass) / dv = -+ (mu - x) P2(x) cosh v / mass, P2 scaled alike */
        float f = upper ? log_target - log(mass) : log(mass) - log_target;
        if (f == 0.0f) break; /* the root to float precision: bisecting on from here only wandered (10 to 30 steps) */
        if (f < 0.0f) lo = fmax(lo, v);
        else hi = fmin(hi, v);
        float slope = (mu - x) * (2.0f * g - 3.0f) * power / mass * sqrt(1.0f + x * x);
        float v_next = hyper_cauchy_next_iterate(v - f / slope, lo, hi);
        if (fabs(v_next - v) <= 1e-7f * fmax(1.0f, fabs(v))) return hyper_cauchy_sinh(v_next);
        v = v_next;
    }
    return hyper_cauchy_sinh(v);
}

/* Student-t with nu = 2g - 1 degrees of freedom, density K (1 + t^2/nu)^(-(nu+1)/2), P(T <= -|t|) =
 * I_{nu/(nu+t^2)}(nu/2, 1/2) / 2: the lower tail is inverted for t <= 0 and mirrored for u > 1/2. */
SS_FN float hyper_cauchy_sample_student_t(float nu, HyperCauchyShape shape, float u) {
    float log_norm = shape.student_log_norm, k = shape.student_k;
    float target = fmin(u, 1.0f - u), log_target = log(target);
    /* The root t < 0 is bracketed by two bounds on the density: it is at most K, so the CDF is at
     * least 1/2 - K |t|; it is below its tail K (t^2/nu)^(-(nu+1)/2), so the CDF is below
     * K nu^((nu-1)/2) |t|^(-nu). Each bound is the root's limit at one end (t -> 0, t -> -inf), and
     * both are widened a little in v against rounding. */
    float t_near = (0.5f - target) / k;
    float t_far = exp((log(k) + 0.5f * (nu - 1.0f) * log(nu) - log_target) / nu);
    float lo = -hyper_cauchy_asinh(t_far) - 1e-3f, hi = fmin(0.0f, 1e-3f - hyper_cauchy_asinh(t_near));
    /* the tail bound is the tighter one in the tail; u = 0 puts it at -inf */
    float v = fmax(target < 0.1f ? lo : hi, HYPER_CAUCHY_LOWEST_V);
    for (int step = 0; step < HYPER_CAUCHY_INVERSION_STEPS; ++step) {
        float t = hyper_cauchy_sinh(v);
        float cdf = 0.5f * incomplete_beta_normed(0.5f * nu, 0.5f, nu / (nu + t * t), log_norm);
        float f = log(cdf) - log_target;
        if (f == 0.0f) break;
        if (f < 0.0f) lo = fmax(lo, v);
        else hi = fmin(hi, v);
        float slope = k * pow(1.0f + t * t / nu, -0.5f * (nu + 1.0f)) / cdf * sqrt(1.0f + t * t);
        float v_next = hyper_cauchy_next_iterate(v - f / slope, lo, hi);
        if (fabs(v_next - v) <= 1e-7f * fmax(1.0f, fabs(v))) {
            v = v_next;
            break;
        }
        v = v_next;
    }
    float t = hyper_cauchy_sinh(v);
    return u < 0.5f ? t : -t;
}

/* Visible normals of w (flipped to the upper side) by stretching to unit width, sampling the visible
 * slopes there and stretching back. pdf(m) = G1(w) max(0, w.m) D(m) / |cos theta_w|, as for GGX. */
SS_FN float3 hyper_cauchy_sample_visible_normal(float3 w, float sx, float sy, float g, HyperCauchyShape shape, float u1, float u2) {
    if (w.z < 0.0f) w = -w; /* the normals visible from below are those of the mirrored direction */
    float3 ws = make_float3(sx * w.x, sy * w.y, w.z);
    float tangential = sqrt(ws.x * ws.x + ws.y * ws.y);
    float cos_phi = tangential > 0.0f ? ws.x / tangential : 1.0f;
    float sin_phi = tangential > 0.0f ? ws.y / tangential : 0.0f;
    /* at normal incidence the visible slopes are the slopes themselves; mu = 1e15 is that to float precision */
    float mu = tangential > ws.z * 1e-15f ? ws.z / tangential : 1e15f;
    float x = hyper_cauchy_sample_visible_slope_x(mu, g, shape, u1);
    float y = sqrt((2.0f + x * x) / (2.0f * g - 1.0f)) * hyper_cauchy_sample_student_t(2.0f * g - 1.0f, shape, u2);
    /* turn back to wo's azimuth and stretch back; the normal of slope (x, y) is (-x, -y, 1) normalised */
    float slope_x = sx * (cos_phi * x - sin_phi * y), slope_y = sy * (sin_phi * x + cos_phi * y);
    return normalize(make_float3(-slope_x, -slope_y, 1.0f));
}

#endif
