#include "scene/scene_bounds.hpp"

#include "scene/geometry_paths.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lab::scene {

void scene_bounds(const Scene& scene, Vec3* center, float* radius) {
    glm::dvec3 lo(scene.camera.position), hi(scene.camera.position);
    auto grow = [&](glm::dvec3 a, glm::dvec3 b) {
        lo = glm::min(lo, a);
        hi = glm::max(hi, b);
    };
    bool endless = false;
    for (const Object& object : scene.objects) {
        const Vec3 e = analyse_shape(object.shape).extent;
        for (int axis = 0; axis < 3; ++axis)
            if (std::isfinite(e[axis])) {
                lo[axis] = std::min(lo[axis], -double(e[axis]));
                hi[axis] = std::max(hi[axis], double(e[axis]));
            } else {
                endless = true;
            }
    }
    if (endless) {
        const glm::dvec3 camera(scene.camera.position);
        const double view = glm::length(glm::dvec3(scene.camera.look_at) - camera);
        grow(camera - view, camera + view);
    }
    for (const Emitter& e : scene.emitters) {
        // a rect's or disk's box: each of its points is x U + y V from the centre, |x|, |y| <= 1/2
        // for a rect's edges, <= 1 for a disk's scaled tangents
        const glm::dvec3 span = glm::abs(glm::dvec3(e.edge_u)) + glm::abs(glm::dvec3(e.edge_v));
        const glm::dvec3 half = e.shape == EmitterShape::sphere ? glm::dvec3(double(e.radius)) : (e.shape == EmitterShape::rect ? 0.5 * span : span);
        grow(glm::dvec3(e.center) - half, glm::dvec3(e.center) + half);
    }
    for (const PointLight& p : scene.point_lights) grow(glm::dvec3(p.position), glm::dvec3(p.position));
    *center = Vec3(0.5 * (lo + hi));
    *radius = float(0.5 * glm::length(hi - lo));
}

void surface_box(const Scene& scene, const SceneAnalysis& analysis, Vec3* lo, Vec3* hi) {
    const float inf = std::numeric_limits<float>::infinity();
    *lo = Vec3(inf);
    *hi = Vec3(-inf);
    // what is intersected exactly is not marched, so the march need not look for it
    for (const Object& object : scene.objects) {
        if (object_is_exact(scene, object)) continue;
        const ShapeAnalysis a = analyse_shape(object.shape);
        Vec3 a_lo = a.box_center - a.box_half, a_hi = a.box_center + a.box_half;
        // the solid of a plane is n.p + offset < 0 (sdf/primitives/plane.h)
        if (const Plane* p = std::get_if<Plane>(&object.shape.kind))
            for (int i = 0; i < 3; ++i) {
                if (p->normal[i] == 1.0f) a_hi[i] = -p->offset;
                if (p->normal[i] == -1.0f) a_lo[i] = p->offset;
            }
        *lo = glm::min(*lo, a_lo);
        *hi = glm::max(*hi, a_hi);
    }
    for (const Emitter& e : scene.emitters) {
        if (emitter_is_exact(scene, e)) continue;
        *lo = glm::min(*lo, e.center - Vec3(e.radius));
        *hi = glm::max(*hi, e.center + Vec3(e.radius));
    }
    if (!analysis.is_distance_bound) *lo = Vec3(-inf), *hi = Vec3(inf);
}

}  // namespace lab::scene
