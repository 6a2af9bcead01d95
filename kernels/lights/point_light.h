/* A point light of intensity I (W sr^-1) at position x: a delta distribution in position, so the
 * only direction from p is towards x, with radiance-like contribution I / |x - p|^2 (no MIS). */
#ifndef KERNELS_LIGHTS_POINT_LIGHT_H
#define KERNELS_LIGHTS_POINT_LIGHT_H
#include "single_source/vocabulary.h"
#include "kernels/lights/light.h"

SS_FN LightSample point_light_sample(const Light* l, float3 p) {
    float3 x = float3_from_array(l->position);
    float3 v = x - p;
    float d2 = dot(v, v);
    if (!(d2 > 0.0f)) return light_sample_none();
    LightSample s;
    s.distance = sqrt(d2);
    s.wi = v / s.distance;
    s.radiance = float3_from_array(l->emission) / d2;
    s.pdf = 1.0f;
    s.position = x;
    s.normal = -s.wi;
    s.delta = 1;
    return s;
}

#endif
