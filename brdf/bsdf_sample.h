/* What a sampler returns. A sample with flags == 0 failed (no direction); delta lobes are
 * flagged, their pdf is the discrete probability of having picked them. */
#ifndef BRDF_BSDF_SAMPLE_H
#define BRDF_BSDF_SAMPLE_H
#include "single_source/vocabulary.h"

#define BSDF_REFLECTION 1
#define BSDF_TRANSMISSION 2
#define BSDF_DELTA 4

typedef struct BsdfSample {
    float3 wi;  /* sampled incident direction, local frame */
    float3 f;   /* BSDF value for (wo, wi); for a delta lobe, its weight divided by |cos theta_i| */
    float pdf;  /* solid-angle density of the whole mixture, = bsdf_pdf(wo, wi); discrete for delta */
    int flags;  /* BSDF_* bits; 0 when sampling failed */
} BsdfSample;

SS_FN BsdfSample bsdf_sample_failed(void) {
    BsdfSample s;
    s.wi = make_float3(0.0f, 0.0f, 1.0f);
    s.f = float3_splat(0.0f);
    s.pdf = 0.0f;
    s.flags = 0;
    return s;
}

#endif
