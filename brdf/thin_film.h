/* Thin-film iridescence: the reflectance of a film (index eta_film, thickness d) between an outside
 * medium (eta_outside) and a dielectric or conductor base, by Belcour and Barla 2017, "A Practical
 * Extension to Microfacet Theory for the Modeling of Varying Iridescence": the Airy sum of the light
 * bouncing inside the film, written per polarisation as a Fourier series in the phase,
 *   R = R12 + Rs + sum_{m>=1} 2 C_m cos(m (delta + phi)),  Rs = T121^2 R23 / (1 - R12 R23),
 *   C_m = (Rs - T121) (|r12| |r23|)^m,  T121 = 1 - R12,  delta = 2 pi OPD / lambda,
 *   OPD = 2 eta_film d cos theta_film,  phi = phase(r21) + phase(r23),
 * so that each harmonic integrates over a spectral sensitivity in closed form. */
#ifndef BRDF_THIN_FILM_H
#define BRDF_THIN_FILM_H
#include "single_source/vocabulary.h"
#include "complex_number.h"
#include "fresnel.h"

/* One interface's amplitude reflection coefficient as magnitude and phase. */
typedef struct FilmAmplitude {
    float magnitude, phase;
} FilmAmplitude;

/* The amplitude from a dielectric (index n_i, cosine c_i) into a medium of complex index
 * n_t = eta + i kappa (kappa = 0: a dielectric), from w = n_t cos_t = sqrt(n_t^2 - n_i^2 sin^2 theta_i),
 * the principal root (the wave decays into an absorbing medium, and past a critical angle w = i q):
 *   r_s = (n_i c_i - w) / (n_i c_i + w),  r_p = (n_t^2 c_i - n_i w) / (n_t^2 c_i + n_i w),
 * fresnel_amplitude's two forms (brdf/fresnel.h) with n_t cos_t written as w, r_p's terms times n_t. */
SS_FN FilmAmplitude film_amplitude(float n_i, float2 n_t, float c_i, int polarisation) {
    float2 n_t2 = complex_mul(n_t, n_t);
    float2 w = complex_sqrt(make_float2(n_t2.x - n_i * n_i * (1.0f - c_i * c_i), n_t2.y));
    float2 a = polarisation == 0 ? make_float2(n_i * c_i, 0.0f) : n_t2 * c_i;
    float2 b = polarisation == 0 ? w : n_i * w;
    float2 r = complex_div(a - b, a + b);
    FilmAmplitude amplitude;
    amplitude.magnitude = complex_abs(r);
    amplitude.phase = atan2(r.y, r.x);
    return amplitude;
}

/* One polarisation's Airy series, each harmonic averaged over a Gaussian spectral sensitivity in
 * wavenumber (mean nu, deviation sigma_nu): the average of cos(m (2 pi OPD nu + phi)) is
 * cos(m (2 pi OPD nu_mean + phi)) exp(-2 (pi m OPD sigma_nu)^2); sigma_nu = 0 is one wavelength.
 * The series stops once the terms left add up to less than 1e-7. */
SS_FN float thin_film_polarised(FilmAmplitude r12, FilmAmplitude r23, float opd, float nu, float sigma_nu) {
    float big_r12 = sqr(r12.magnitude), t121 = 1.0f - big_r12, big_r23 = sqr(r23.magnitude);
    float loss = 1.0f - big_r12 * big_r23;
    if (!(loss > 0.0f)) return 1.0f; /* both interfaces mirrors */
    float rs = t121 * t121 * big_r23 / loss;
    float r123 = r12.magnitude * r23.magnitude;
    float phase = 2.0f * SS_PI * opd * nu + (r12.phase + SS_PI) + r23.phase; /* r21 = -r12 */
    float spread = 2.0f * sqr(SS_PI * opd * sigma_nu);
    float reflectance = big_r12 + rs, c_m = rs - t121;
    int m;
    for (m = 1; m <= 64; ++m) {
        c_m *= r123; /* C_m */
        float fm = (float)m;
        float term = 2.0f * c_m * exp(-fm * fm * spread);
        if (fabs(term) < 1e-7f * (1.0f - r123)) return clamp(reflectance, 0.0f, 1.0f); /* the rest is below 1e-7 */
        reflectance += term * cos(fm * phase);
    }
    /* |r12 r23| near 1 (grazing light on a film over a metal): the rest, sum over m >= 65 of
     * 2 C_m cos(m psi), is the geometric series' 2 C_65 (cos(65 psi) - r cos(64 psi)) / (1 - 2 r cos psi + r^2),
     * r = |r12 r23|, damped as its first term: exact at one wavelength. */
    c_m *= r123;
    float tail = 2.0f * c_m * exp(-4225.0f * spread) * (cos(65.0f * phase) - r123 * cos(64.0f * phase)) /
                 (1.0f - 2.0f * r123 * cos(phase) + r123 * r123);
    return clamp(reflectance + tail, 0.0f, 1.0f);
}

/* The light's path through the film: the incidence cosines outside and inside, the optical path
 * difference 2 eta_film d cos theta_film, and whether it is past the outside-to-film critical angle
 * (the film then reflects everything; frustrated total reflection through a film thinner than a
 * wavelength is left out, as Belcour and Barla do). */
typedef struct FilmPath {
    float cos_outside, cos_film, opd;
    int reflects_all;
} FilmPath;

SS_FN FilmPath film_path(float cos_outside, float eta_outside, float eta_film, float thickness_um) {
    FilmPath path;
    path.cos_outside = clamp(cos_outside, 0.0f, 1.0f);
    float sin2_film = sqr(eta_outside / eta_film) * (1.0f - path.cos_outside * path.cos_outside);
    path.reflects_all = sin2_film >= 1.0f;
    path.cos_film = path.reflects_all ? 0.0f : sqrt(1.0f - sin2_film);
    path.opd = 2.0f * eta_film * thickness_um * path.cos_film;
    return path;
}

/* Unpolarised reflectance of the film over a base of complex index n_base (kappa = 0: a dielectric)
 * at incidence cosine cos_outside, thickness in micrometres, nu and sigma_nu in 1/micrometre. */
SS_FN float thin_film_airy(float cos_outside, float eta_outside, float eta_film, float2 n_base, float thickness_um,
                           float nu, float sigma_nu) {
    FilmPath path = film_path(cos_outside, eta_outside, eta_film, thickness_um);
    if (path.reflects_all) return 1.0f;
    float sum = 0.0f;
    for (int polarisation = 0; polarisation < 2; ++polarisation) {
        FilmAmplitude r12 = film_amplitude(eta_outside, make_float2(eta_film, 0.0f), path.cos_outside, polarisation);
        FilmAmplitude r23 = film_amplitude(eta_film, n_base, path.cos_film, polarisation);
        sum += thin_film_polarised(r12, r23, path.opd, nu, sigma_nu);
    }
    return 0.5f * sum;
}

/* The film over a dielectric base. Thickness 0 is no film: the base's own Fresnel reflectance. */
SS_FN float thin_film_reflectance(float cos_outside, float eta_outside, float eta_film, float eta_base,
                                  float thickness_um, float nu, float sigma_nu) {
    if (!(thickness_um > 0.0f)) return fresnel_dielectric(clamp(cos_outside, 0.0f, 1.0f), eta_base / eta_outside);
    return thin_film_airy(cos_outside, eta_outside, eta_film, make_float2(eta_base, 0.0f), thickness_um, nu, sigma_nu);
}

/* The film over a conductor of complex index n_base = eta + i kappa (Belcour and Barla's conductor
 * case: r23 has a phase of its own). Thickness 0 is the bare conductor's Fresnel reflectance. */
SS_FN float thin_film_conductor_reflectance(float cos_outside, float eta_outside, float eta_film, float2 n_base,
                                            float thickness_um, float nu, float sigma_nu) {
    if (thickness_um > 0.0f) return thin_film_airy(cos_outside, eta_outside, eta_film, n_base, thickness_um, nu, sigma_nu);
    float c1 = clamp(cos_outside, 0.0f, 1.0f);
    return 0.5f * (sqr(film_amplitude(eta_outside, n_base, c1, 0).magnitude) + sqr(film_amplitude(eta_outside, n_base, c1, 1).magnitude));
}

/* A conductor's complex index eta + i kappa from its normal reflectance r and an edge tint g in
 * [0, 1], by Gulbrandsen 2014 ("Artist Friendly Metallic Fresnel"): eta runs from
 * n_max = (1 + sqrt r) / (1 - sqrt r) (g = 0, kappa = 0) down to n_min = (1 - r) / (1 + r) (g = 1),
 * eta = g n_min + (1 - g) n_max, and kappa solves ((eta - 1)^2 + kappa^2) / ((eta + 1)^2 + kappa^2) = r,
 * so the conductor reflects exactly r at normal incidence. r is held below 0.99, where n_max is finite. */
SS_FN float2 conductor_index_from_tint(float r, float g) {
    r = clamp(r, 0.0f, 0.99f);
    float sqrt_r = sqrt(r);
    float n_min = (1.0f - r) / (1.0f + r), n_max = (1.0f + sqrt_r) / (1.0f - sqrt_r);
    float eta = mix(n_max, n_min, clamp(g, 0.0f, 1.0f));
    float kappa2 = (sqr(eta + 1.0f) * r - sqr(eta - 1.0f)) / (1.0f - r);
    return make_float2(eta, sqrt(fmax(kappa2, 0.0f)));
}

/* What a film (thickness > 0) changes of the reflectance of a conductor of complex index n_base,
 * outside index 1: the film's reflectance less the bare conductor's. */
SS_FN float thin_film_conductor_change(float cos_outside, float eta_film, float2 n_base, float thickness_um, float nu, float sigma_nu) {
    return thin_film_airy(cos_outside, 1.0f, eta_film, n_base, thickness_um, nu, sigma_nu) -
           thin_film_conductor_reflectance(cos_outside, 1.0f, eta_film, n_base, 0.0f, nu, sigma_nu);
}

/* The RGB renderer's three channels as Gaussians in wavenumber (Belcour and Barla integrate against
 * Gaussian fits of CIE XYZ instead): centred on 610, 550 and 465 nm, deviation 0.1 / micrometre
 * (about +-30 nm at 550 nm), so a film a few micrometres thick averages to its incoherent sum. */
#define THIN_FILM_NU_R (1.0f / 0.610f)
#define THIN_FILM_NU_G (1.0f / 0.550f)
#define THIN_FILM_NU_B (1.0f / 0.465f)
#define THIN_FILM_SIGMA_NU 0.1f

SS_FN float3 thin_film_reflectance_rgb(float cos_outside, float eta_outside, float eta_film, float eta_base,
                                       float thickness_um) {
    if (!(thickness_um > 0.0f)) return float3_splat(thin_film_reflectance(cos_outside, eta_outside, eta_film, eta_base, thickness_um, 0.0f, 0.0f));
    /* thin_film_airy per channel, the interfaces' amplitudes computed once: over a dielectric they
     * do not depend on the wavelength, only the phase does (the same arithmetic, so the same bits) */
    FilmPath path = film_path(cos_outside, eta_outside, eta_film, thickness_um);
    if (path.reflects_all) return float3_splat(1.0f);
    float3 sum = float3_splat(0.0f);
    for (int polarisation = 0; polarisation < 2; ++polarisation) {
        FilmAmplitude r12 = film_amplitude(eta_outside, make_float2(eta_film, 0.0f), path.cos_outside, polarisation);
        FilmAmplitude r23 = film_amplitude(eta_film, make_float2(eta_base, 0.0f), path.cos_film, polarisation);
        sum.x += thin_film_polarised(r12, r23, path.opd, THIN_FILM_NU_R, THIN_FILM_SIGMA_NU);
        sum.y += thin_film_polarised(r12, r23, path.opd, THIN_FILM_NU_G, THIN_FILM_SIGMA_NU);
        sum.z += thin_film_polarised(r12, r23, path.opd, THIN_FILM_NU_B, THIN_FILM_SIGMA_NU);
    }
    return 0.5f * sum;
}

/* Over a conductor: the base's complex index per channel, eta + i kappa. */
SS_FN float3 thin_film_conductor_reflectance_rgb(float cos_outside, float eta_outside, float eta_film, float3 eta_base,
                                                 float3 kappa_base, float thickness_um) {
    return make_float3(thin_film_conductor_reflectance(cos_outside, eta_outside, eta_film, make_float2(eta_base.x, kappa_base.x),
                                                       thickness_um, THIN_FILM_NU_R, THIN_FILM_SIGMA_NU),
                       thin_film_conductor_reflectance(cos_outside, eta_outside, eta_film, make_float2(eta_base.y, kappa_base.y),
                                                       thickness_um, THIN_FILM_NU_G, THIN_FILM_SIGMA_NU),
                       thin_film_conductor_reflectance(cos_outside, eta_outside, eta_film, make_float2(eta_base.z, kappa_base.z),
                                                       thickness_um, THIN_FILM_NU_B, THIN_FILM_SIGMA_NU));
}

#endif
