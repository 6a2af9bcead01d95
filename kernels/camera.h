/* The camera: a pinhole or a thin lens, for camera rays (path tracing) and for connections to the
 * lens (light tracing, BDPT's t = 1), after pbrt-v4's PerspectiveCamera. Plain float arrays, not
 * float3, so the struct has one layout on the host and in OpenCL C and travels as a kernel
 * argument by value.
 *
 * Geometry. The film is the rectangle at distance 1 in front of the camera, centre
 * position + forward, spanned by right and up (scaled to the film's half width and half height
 * there), so raster (x, y) in pixels from the top-left corner is the film point
 *   forward + sx right + sy up,  sx = 2 x / width - 1,  sy = 1 - 2 y / height,
 * and the film's area is A = 4 |right| |up|. A pinhole (lens_radius 0) sends the ray from position
 * through that point. A thin lens of radius R focused at distance F sends it from a point on the
 * lens disk (position + R (lx right/|right| + ly up/|up|)) through the point where the pinhole ray
 * crosses the plane of focus, position + F (forward + sx right + sy up): points on that plane image
 * sharply, a point at depth z to a disk of radius R |1/F - 1/z| on the film at distance 1.
 *
 * Importance (Veach 1997, sec. 8.1.3; pbrt-v4 PerspectiveCamera::We). For a ray leaving the lens at
 * angle theta to forward and landing on the film,
 *   W_e = 1 / (A * lens_area * cos^4 theta),  lens_area = pi R^2 (1 for the pinhole),
 * 0 elsewhere. Normalisation: for the pinhole, integral of W_e cos theta over the film's
 * directions = 1 (d omega = cos^3 theta dA_film); for the lens, the same per lens point, times
 * 1 / lens_area. A pixel's box-filter measurement is I_j = integral of (width height W_e [in pixel j])
 * L cos theta, so a light tracer that follows one light path per pixel and sample
 * (width * height * spp paths) and splats importance * contribution / pdf into the pixel of the
 * returned raster position, then divides every pixel by spp, estimates the same pixel values as
 * the path tracer (which averages L over the pixel). */
#ifndef KERNELS_CAMERA_H
#define KERNELS_CAMERA_H
#include "single_source/vocabulary.h"
#include "brdf/warp.h"
#include "kernels/rng.h"

typedef struct Camera {
    float position[3];
    float forward[3]; /* unit view direction */
    float right[3];   /* scaled to the image's half width at distance 1: tan(fov / 2) * aspect */
    float up[3];      /* scaled to the image's half height at distance 1: tan(fov / 2) */
    int width, height;
    float lens_radius;    /* 0: pinhole */
    float focus_distance; /* thin lens only: the distance of the plane in focus along forward */
} Camera;

/* A light-tracing connection from a world point to the lens. */
typedef struct CameraSample {
    float2 raster;     /* pixels from the top-left image corner */
    float3 lens_point; /* the point on the lens (the camera position for a pinhole) */
    float3 wi;         /* unit, from the world point towards lens_point */
    float distance;    /* from the world point to lens_point */
    float importance;  /* W_e of the ray from lens_point towards the world point */
    float pdf;         /* solid-angle density of wi at the world point: d^2 / (cos theta lens_area) */
    int visible;       /* 0: behind the camera, outside the film, or degenerate; the rest is then 0 */
} CameraSample;

/* The pinhole ray's direction through raster (x, y), unnormalised, with unit length along forward, in
 * components: one ray, or (SDF_LANES) the eight rays of a packet kernel's lanes
 * (kernels/march_packets.cl), each lane the bits of the one-ray form. */
SS_FN void camera_film_point_xyz(const Camera* c, SDF_FLOAT x, SDF_FLOAT y, SDF_FLOAT* fx, SDF_FLOAT* fy, SDF_FLOAT* fz) {
    SDF_FLOAT sx = 2.0f * x / (float)c->width - 1.0f;
    SDF_FLOAT sy = 1.0f - 2.0f * y / (float)c->height;
    *fx = c->forward[0] + sx * c->right[0] + sy * c->up[0];
    *fy = c->forward[1] + sx * c->right[1] + sy * c->up[1];
    *fz = c->forward[2] + sx * c->right[2] + sy * c->up[2];
}

/* (x, y, z) scaled to unit length as OpenCL's normalize() scales a vector of ordinary length (PoCL:
 * times the reciprocal of the square root of x^2 + y^2 + z^2, the same bits), in components. */
SS_FN void camera_unit_xyz(SDF_FLOAT* x, SDF_FLOAT* y, SDF_FLOAT* z) {
    SDF_FLOAT inverse_length = 1.0f / sqrt(*x * *x + *y * *y + *z * *z);
    *x = *x * inverse_length;
    *y = *y * inverse_length;
    *z = *z * inverse_length;
}

#ifndef SDF_LANES /* the rest: one ray at a time */
SS_FN float camera_lens_area(const Camera* c) { return c->lens_radius > 0.0f ? SS_PI * sqr(c->lens_radius) : 1.0f; }

SS_FN float camera_film_area(const Camera* c) {
    return 4.0f * length(float3_from_array(c->right)) * length(float3_from_array(c->up));
}

/* The pinhole ray's direction through raster (x, y), unnormalised, with unit length along forward. */
SS_FN float3 camera_film_point(const Camera* c, float x, float y) {
    float fx, fy, fz;
    camera_film_point_xyz(c, x, y, &fx, &fy, &fz);
    return make_float3(fx, fy, fz);
}

/* The point of the lens for two uniform numbers (concentric disk, uniform by area). */
SS_FN float3 camera_lens_point(const Camera* c, float2 u_lens) {
    float3 origin = float3_from_array(c->position);
    if (!(c->lens_radius > 0.0f)) return origin;
    float2 disk = square_to_concentric_disk(u_lens.x, u_lens.y) * c->lens_radius;
    return origin + disk.x * normalize(float3_from_array(c->right)) + disk.y * normalize(float3_from_array(c->up));
}

/* The camera ray through raster (x, y) (pixels from the top-left corner, jittered by the caller)
 * from the lens point of u_lens (ignored by the pinhole). *direction is unit. */
SS_FN void camera_generate_ray(const Camera* c, float x, float y, float2 u_lens, float3* origin, float3* direction) {
    float3 film = camera_film_point(c, x, y);
    if (!(c->lens_radius > 0.0f)) {
        *origin = float3_from_array(c->position);
        float x = film.x, y = film.y, z = film.z;
        camera_unit_xyz(&x, &y, &z); /* as the packets' camera rays (kernels/march_packets.cl) */
        *direction = make_float3(x, y, z);
        return;
    }
    float3 focus = float3_from_array(c->position) + film * c->focus_distance;
    *origin = camera_lens_point(c, u_lens);
    *direction = normalize(focus - *origin);
}

/* The camera ray of one sample of pixel k ((k % width, k / width), row 0 at the top) from its random
 * stream's next four numbers: xy jitter the point within the pixel (a box filter), zw pick the lens
 * point. The path tracer (one work-item's paths, and the wavefront's camera step) and BDPT's camera
 * subpath (kernels/bdpt_walk.h) draw it alike. */
SS_FN void camera_pixel_ray(const Camera* c, int pixel, Rng* rng, float3* origin, float3* direction) {
    float x = (float)(pixel % c->width), y = (float)(pixel / c->width);
    float4 u = rng_next4(rng);
    camera_generate_ray(c, x + u.x, y + u.y, make_float2(u.z, u.w), origin, direction);
}

/* Where a ray from lens point `origin` along unit `direction` lands on the raster: through the
 * plane of focus (the film itself for the pinhole). Returns cos theta to forward; the raster is
 * set only when it is positive. */
SS_FN float camera_raster(const Camera* c, float3 origin, float3 direction, float2* raster) {
    float3 forward = float3_from_array(c->forward);
    float cos_theta = dot(direction, forward);
    if (!(cos_theta > 0.0f)) return 0.0f;
    float focus = c->lens_radius > 0.0f ? c->focus_distance : 1.0f;
    /* the film point relative to position, scaled to distance 1 */
    float3 q = (origin - float3_from_array(c->position) + direction * (focus / cos_theta)) / focus;
    float3 right = float3_from_array(c->right), up = float3_from_array(c->up);
    float sx = dot(q, right) / dot(right, right);
    float sy = dot(q, up) / dot(up, up);
    *raster = make_float2((sx + 1.0f) * 0.5f * (float)c->width, (1.0f - sy) * 0.5f * (float)c->height);
    return cos_theta;
}

SS_FN bool camera_raster_inside(const Camera* c, float2 raster) {
    return raster.x >= 0.0f && raster.x < (float)c->width && raster.y >= 0.0f && raster.y < (float)c->height;
}

/* W_e of the ray leaving lens point `origin` along unit `direction`, and its raster position;
 * 0 when it points away from the film or lands outside it. (pbrt's We(ray) also takes the ray's
 * origin: through a thin lens, the raster depends on where on the lens the ray starts.) */
SS_FN float camera_importance(const Camera* c, float3 origin, float3 direction, float2* raster) {
    float cos_theta = camera_raster(c, origin, direction, raster);
    if (!(cos_theta > 0.0f) || !camera_raster_inside(c, *raster)) return 0.0f;
    float cos2 = cos_theta * cos_theta;
    return 1.0f / (camera_film_area(c) * camera_lens_area(c) * cos2 * cos2);
}

/* The densities of a ray leaving the camera as camera_generate_ray() draws it with a uniform
 * raster position: per unit lens area, 1 / lens_area (1 for the pinhole, whose position is a
 * delta), and per solid angle, 1 / (A cos^3 theta); both 0 off the film. */
SS_FN void camera_pdf_we(const Camera* c, float3 origin, float3 direction, float* pdf_position, float* pdf_direction) {
    float2 raster;
    float cos_theta = camera_raster(c, origin, direction, &raster);
    if (!(cos_theta > 0.0f) || !camera_raster_inside(c, raster)) {
        *pdf_position = 0.0f;
        *pdf_direction = 0.0f;
        return;
    }
    *pdf_position = 1.0f / camera_lens_area(c);
    *pdf_direction = 1.0f / (camera_film_area(c) * cos_theta * cos_theta * cos_theta);
}

/* A point on the lens (u_lens) seen from world point p: the connection light tracing splats. */
SS_FN CameraSample camera_sample_wi(const Camera* c, float3 p, float2 u_lens) {
    CameraSample s;
    s.raster = make_float2(0.0f, 0.0f);
    s.lens_point = camera_lens_point(c, u_lens);
    s.wi = make_float3(0.0f, 0.0f, 1.0f);
    s.distance = 0.0f;
    s.importance = 0.0f;
    s.pdf = 0.0f;
    s.visible = 0;
    float3 v = s.lens_point - p;
    float dist = length(v);
    if (!(dist > 0.0f)) return s;
    float3 wi = v / dist;
    float2 raster;
    float importance = camera_importance(c, s.lens_point, -wi, &raster);
    if (!(importance > 0.0f)) return s;
    float cos_lens = dot(-wi, float3_from_array(c->forward)); /* the lens faces forward */
    s.raster = raster;
    s.wi = wi;
    s.distance = dist;
    s.importance = importance;
    s.pdf = dist * dist / (cos_lens * camera_lens_area(c));
    s.visible = 1;
    return s;
}

#else /* SDF_LANES */
/* camera_pixel_ray of a pinhole for eight pixels at once, on a packet kernel's lanes
 * (kernels/march_packets.cl): each lane draws its path's four numbers from its generator and gets
 * the bits of camera_pixel_ray's direction; the origin is the camera's position. */
SS_FN void camera_pinhole_pixel_rays(const Camera* c, SDF_MASK pixel, RngLanes* rng, SDF_FLOAT* dx, SDF_FLOAT* dy, SDF_FLOAT* dz) {
    SDF_FLOAT x = convert_float8(pixel % c->width), y = convert_float8(pixel / c->width);
    SDF_FLOAT ux = rng_next_float_lanes(rng);
    SDF_FLOAT uy = rng_next_float_lanes(rng);
    rng_next_float_lanes(rng); /* the lens point's two numbers: a pinhole draws them and has no lens */
    rng_next_float_lanes(rng);
    camera_film_point_xyz(c, x + ux, y + uy, dx, dy, dz);
    camera_unit_xyz(dx, dy, dz);
}
#endif /* SDF_LANES */

#endif
