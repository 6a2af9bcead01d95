/* Directions in the local shading frame: z is the normal, x the (unrotated) tangent. */
#ifndef BRDF_FRAME_H
#define BRDF_FRAME_H
#include "single_source/vocabulary.h"

SS_FN float cos_theta(float3 w) { return w.z; }
SS_FN float cos2_theta(float3 w) { return w.z * w.z; }
SS_FN float sin2_theta(float3 w) { return fmax(0.0f, 1.0f - w.z * w.z); }
SS_FN bool same_hemisphere(float3 a, float3 b) { return a.z * b.z > 0.0f; }

/* Rotation about the normal, used to turn the anisotropy tangent. Most materials have none: then w
 * is returned as it is, without a cos and a sin (OpenCL on a CPU reduces their argument in a call of
 * its own), which the rotation by 0 would give but for the sign of a zero component. */
SS_FN float3 rotate_about_normal(float3 w, float angle) {
    if (angle == 0.0f) return w;
    float c = cos(angle), s = sin(angle);
    return make_float3(c * w.x - s * w.y, s * w.x + c * w.y, w.z);
}

SS_FN float3 reflect_about(float3 w, float3 n) { return 2.0f * dot(w, n) * n - w; }

/* Refracts w (pointing away from the surface, on the side n faces) through the interface with
 * relative index eta = eta_transmitted / eta_incident. Returns false on total internal reflection. */
SS_FN bool refract_through(float3 w, float3 n, float eta, float3* wt) {
    float cos_i = dot(n, w);
    float sin2_t = fmax(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f) return false;
    float cos_t = safe_sqrt(1.0f - sin2_t);
    *wt = -w / eta + (cos_i / eta - cos_t) * n;
    return true;
}

/* Orthonormal basis around a unit normal (Duff et al. 2017), for consumers in world space. */
typedef struct ShadingFrame { float3 t, b, n; } ShadingFrame;

SS_FN ShadingFrame frame_from_normal(float3 n) {
    float sign = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    ShadingFrame f;
    f.t = make_float3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.b = make_float3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

/* A frame whose x axis follows a given tangent (Gram-Schmidt against n). */
SS_FN ShadingFrame frame_from_normal_tangent(float3 n, float3 tangent) {
    float3 t = tangent - n * dot(n, tangent);
    float len = length(t);
    if (!(len > 1e-6f)) return frame_from_normal(n);
    ShadingFrame f;
    f.t = t / len;
    f.b = cross(n, f.t);
    f.n = n;
    return f;
}

SS_FN float3 frame_to_local(ShadingFrame f, float3 w) { return make_float3(dot(w, f.t), dot(w, f.b), dot(w, f.n)); }
SS_FN float3 frame_to_world(ShadingFrame f, float3 w) { return w.x * f.t + w.y * f.b + w.z * f.n; }

#endif
