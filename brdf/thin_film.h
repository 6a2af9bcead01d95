/* Thin-film iridescence: the reflectance of a film (index eta_film, thickness d) between an outside
 * medium (eta_outside) and a dielectric base (eta_base), by Belcour and Barla 2017, "A Practical
 * Extension to Microfacet Theory for the Modeling of Varying Iridescence": the Airy sum of the light
 * bouncing inside the film, written per polarisation as a Fourier series in the phase,
 *   R = R12 + Rs + sum_{m>=1} 2 C_m cos(m (delta + phi)),  Rs = T121^2 R23 / (1 - R12 R23),
 *   C_m = (Rs - T121) (|r12| |r23|)^m,  T121 = 1 - R12,  delta = 2 pi OPD / lambda,
 *   OPD = 2 eta_film d cos theta_film,  phi = phase(r21) + phase(r23),
 * so that each harmonic integrates over a spectral sensitivity in closed form. */
#ifndef BRDF_THIN_FILM_H
#define BRDF_THIN_FILM_H
#include "single_source/vocabulary.h"
#include "fresnel.h"

/* One interface's amplitude reflection coefficient as magnitude and phase. */
typedef struct FilmAmplitude {
    float magnitude, phase;
} FilmAmplitude;

SS_FN FilmAmplitude film_amplitude_real(float r) {
    FilmAmplitude a;
    a.magnitude = fabs(r);
    a.phase = r < 0.0f ? SS_PI : 0.0f;
    return a;
}

/* Fresnel amplitude (fresnel_amplitude) from index n_i into n_t at cosine c_i, s-polarised
 * (polarisation 0) or p-polarised (1). Past the critical angle c_t = i q, q = sqrt(sin^2 theta_t - 1):
 * (a c_i - i b q) / (a c_i + i b q) has modulus 1 and phase -2 atan2(b q, a c_i). */
SS_FN FilmAmplitude film_interface_amplitude(float n_i, float n_t, float c_i, int polarisation) {
    float sin2_t = sqr(n_i / n_t) * (1.0f - c_i * c_i);
    float a = polarisation == 0 ? n_i : n_t, b = polarisation == 0 ? n_t : n_i;
    if (sin2_t > 1.0f) {
        FilmAmplitude r;
        r.magnitude = 1.0f;
        r.phase = -2.0f * atan2(b * sqrt(sin2_t - 1.0f), a * c_i);
        return r;
    }
    return film_amplitude_real(fresnel_amplitude(a, b, c_i, sqrt(1.0f - sin2_t)));
}

/* One polarisation's Airy series, each harmonic averaged over a Gaussian spectral sensitivity in
 * wavenumber (mean nu, deviation sigma_nu): the average of cos(m (2 pi OPD nu + phi)) is
 * cos(m (2 pi OPD nu_mean + phi)) exp(-2 (pi m OPD sigma_nu)^2); sigma_nu = 0 is one wavelength.
 * The series stops once a term's amplitude is below 1e-7 (at most 16 terms). */
SS_FN float thin_film_polarised(FilmAmplitude r12, FilmAmplitude r23, float opd, float nu, float sigma_nu) {
    float big_r12 = sqr(r12.magnitude), t121 = 1.0f - big_r12, big_r23 = sqr(r23.magnitude);
    float loss = 1.0f - big_r12 * big_r23;
    if (!(loss > 0.0f)) return 1.0f; /* both interfaces mirrors */
    float rs = t121 * t121 * big_r23 / loss;
    float r123 = r12.magnitude * r23.magnitude;
    float phase = 2.0f * SS_PI * opd * nu + (r12.phase + SS_PI) + r23.phase; /* r21 = -r12 */
    float spread = 2.0f * sqr(SS_PI * opd * sigma_nu);
    float reflectance = big_r12 + rs, c_m = rs - t121;
    for (int m = 1; m <= 16; ++m) {
        c_m *= r123;
        if (fabs(c_m) < 1e-7f) break;
        float fm = (float)m;
        reflectance += 2.0f * c_m * cos(fm * phase) * exp(-fm * fm * spread);
    }
    return clamp(reflectance, 0.0f, 1.0f);
}

/* Unpolarised reflectance of the film over a dielectric base at incidence cosine cos_outside,
 * thickness in micrometres, nu and sigma_nu in 1/micrometre. A film of thickness 0 is no film: the
 * base's own Fresnel reflectance. Past the outside-to-film critical angle the film reflects
 * everything (frustrated total reflection through a film thinner than a wavelength is left out, as
 * Belcour and Barla do). */
SS_FN float thin_film_reflectance(float cos_outside, float eta_outside, float eta_film, float eta_base,
                                  float thickness_um, float nu, float sigma_nu) {
    float c1 = clamp(cos_outside, 0.0f, 1.0f);
    if (!(thickness_um > 0.0f)) return fresnel_dielectric(c1, eta_base / eta_outside);
    float sin2_film = sqr(eta_outside / eta_film) * (1.0f - c1 * c1);
    if (sin2_film >= 1.0f) return 1.0f;
    float c2 = sqrt(1.0f - sin2_film);
    float opd = 2.0f * eta_film * thickness_um * c2;
    float sum = 0.0f;
    for (int polarisation = 0; polarisation < 2; ++polarisation) {
        FilmAmplitude r12 = film_interface_amplitude(eta_outside, eta_film, c1, polarisation);
        FilmAmplitude r23 = film_interface_amplitude(eta_film, eta_base, c2, polarisation);
        sum += thin_film_polarised(r12, r23, opd, nu, sigma_nu);
    }
    return 0.5f * sum;
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
    return make_float3(
        thin_film_reflectance(cos_outside, eta_outside, eta_film, eta_base, thickness_um, THIN_FILM_NU_R, THIN_FILM_SIGMA_NU),
        thin_film_reflectance(cos_outside, eta_outside, eta_film, eta_base, thickness_um, THIN_FILM_NU_G, THIN_FILM_SIGMA_NU),
        thin_film_reflectance(cos_outside, eta_outside, eta_film, eta_base, thickness_um, THIN_FILM_NU_B, THIN_FILM_SIGMA_NU));
}

#endif
