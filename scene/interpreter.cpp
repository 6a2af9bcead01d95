#include "scene/interpreter.hpp"

#include "scene/emitter_geometry.hpp"
#include "scene/geometry_paths.hpp"
#include "scene/rotation.hpp"
#include "sdf/sdf.hpp"

#include <cmath>

namespace lab::scene {
namespace {

float primitive_distance(const NodeKind& kind, Vec3 p) {
    if (auto* s = std::get_if<Sphere>(&kind)) return sdf::fSphere(p, s->radius);
    if (auto* q = std::get_if<Plane>(&kind)) return sdf::fPlane(p, q->normal, q->offset);
    if (auto* b = std::get_if<Box>(&kind)) return sdf::fBox(p, b->half_size);
    if (auto* b = std::get_if<RoundBox>(&kind)) return sdf::fRoundBox(p, b->half_size, b->radius);
    if (auto* t = std::get_if<Torus>(&kind)) return sdf::fTorus(p, t->major_radius, t->minor_radius);
    if (auto* c = std::get_if<Cylinder>(&kind)) return sdf::fCylinder(p, c->radius, c->half_height);
    if (auto* c = std::get_if<Capsule>(&kind)) return sdf::fCapsule(p, c->radius, c->half_height);
    if (auto* c = std::get_if<Cone>(&kind)) return sdf::fCone(p, c->radius, c->height);
    return 0.0f;
}

bool primitive_normal(const NodeKind& kind, Vec3 p, Vec3* n) {
    if (auto* s = std::get_if<Sphere>(&kind)) *n = sdf::nSphere(p, s->radius);
    else if (auto* q = std::get_if<Plane>(&kind)) *n = sdf::nPlane(p, q->normal, q->offset);
    else if (auto* b = std::get_if<Box>(&kind)) *n = sdf::nBox(p, b->half_size);
    else if (auto* b = std::get_if<RoundBox>(&kind)) *n = sdf::nRoundBox(p, b->half_size, b->radius);
    else if (auto* t = std::get_if<Torus>(&kind)) *n = sdf::nTorus(p, t->major_radius, t->minor_radius);
    else if (auto* c = std::get_if<Cylinder>(&kind)) *n = sdf::nCylinder(p, c->radius, c->half_height);
    else if (auto* c = std::get_if<Capsule>(&kind)) *n = sdf::nCapsule(p, c->radius, c->half_height);
    else if (auto* c = std::get_if<Cone>(&kind)) *n = sdf::nCone(p, c->radius, c->height);
    else return false;
    return true;
}

float primitive_exact_hit(const NodeKind& kind, Vec3 o, Vec3 v, float t_max) {
    if (auto* s = std::get_if<Sphere>(&kind)) return sdf::xSphere(o, v, s->radius, t_max);
    if (auto* q = std::get_if<Plane>(&kind)) return sdf::xPlane(o, v, q->normal, q->offset, t_max);
    if (auto* b = std::get_if<Box>(&kind)) return sdf::xBox(o, v, b->half_size, t_max);
    if (auto* b = std::get_if<RoundBox>(&kind)) return sdf::xRoundBox(o, v, b->half_size, b->radius, t_max);
    if (auto* t = std::get_if<Torus>(&kind)) return sdf::xTorus(o, v, t->major_radius, t->minor_radius, t_max);
    if (auto* c = std::get_if<Cylinder>(&kind)) return sdf::xCylinder(o, v, c->radius, c->half_height, t_max);
    if (auto* c = std::get_if<Capsule>(&kind)) return sdf::xCapsule(o, v, c->radius, c->half_height, t_max);
    if (auto* c = std::get_if<Cone>(&kind)) return sdf::xCone(o, v, c->radius, c->height, t_max);
    return EXACT_MISS;
}

// As the compiled hit functions (emit_exact_hit): the ray down to the primitive's frame.
float shape_exact_hit(const Node& node, Vec3 o, Vec3 v, float t_max) {
    if (node.children.empty()) return primitive_exact_hit(node.kind, o, v, t_max);
    const Node& child = node.children[0];
    if (auto* t = std::get_if<Translate>(&node.kind)) return shape_exact_hit(child, o - t->offset, v, t_max);
    if (auto* r = std::get_if<Rotate>(&node.kind))
        return shape_exact_hit(child, apply_rotation(r->rotation, o, true), apply_rotation(r->rotation, v, true), t_max);
    auto* s = std::get_if<Scale>(&node.kind);
    return s->factor * shape_exact_hit(child, o / s->factor, v, t_max / s->factor);
}

float combine(Combinator op, float a, float b, float r) {
    switch (op) {
    case Combinator::union_: return sdf::fOpUnion(a, b);
    case Combinator::intersection: return sdf::fOpIntersection(a, b);
    case Combinator::subtraction: return sdf::fOpSubtraction(a, b);
    case Combinator::smooth_union: return sdf::fOpUnionSmooth(a, b, r);
    case Combinator::round_union: return sdf::fOpUnionRound(a, b, r);
    case Combinator::round_intersection: return sdf::fOpIntersectionRound(a, b, r);
    case Combinator::round_subtraction: return sdf::fOpSubtractionRound(a, b, r);
    case Combinator::chamfer_union: return sdf::fOpUnionChamfer(a, b, r);
    case Combinator::chamfer_intersection: return sdf::fOpIntersectionChamfer(a, b, r);
    case Combinator::chamfer_subtraction: return sdf::fOpSubtractionChamfer(a, b, r);
    }
    return a;
}

// As the compiled normal functions: transforms down to the primitive, rotations back up.
bool shape_normal(const Node& node, Vec3 p, Vec3* n) {
    if (node.children.empty()) return primitive_normal(node.kind, p, n);
    const Node& child = node.children[0];
    if (auto* t = std::get_if<Translate>(&node.kind)) return shape_normal(child, p - t->offset, n);
    if (auto* s = std::get_if<Scale>(&node.kind)) return shape_normal(child, p / s->factor, n);
    if (auto* r = std::get_if<Rotate>(&node.kind)) {
        Vec3 local;
        if (!shape_normal(child, apply_rotation(r->rotation, p, true), &local)) return false;
        *n = apply_rotation(r->rotation, local, false);
        return true;
    }
    return false;
}

// An emitter's distance, exact hit and normal, as the generated scene calls them
// (scene/generated_source.cpp): the same functions on the same floats.
float emitter_distance(const Emitter& e, Vec3 p) {
    const Vec3 q = p - e.center;
    if (e.shape == EmitterShape::rect) return sdf::fRect_xyz(q.x, q.y, q.z, e.edge_u, e.edge_v, e.normal, rect_dual_u(e), rect_dual_v(e));
    if (e.shape == EmitterShape::disk) return sdf::fDisk_xyz(q.x, q.y, q.z, e.normal, e.radius);
    return sdf::fSphere(q, e.radius);
}

float emitter_exact_hit(const Emitter& e, Vec3 o, Vec3 v, float t_max) {
    if (e.shape == EmitterShape::rect) return sdf::xRect(o - e.center, v, e.normal, rect_dual_u(e), rect_dual_v(e), t_max);
    if (e.shape == EmitterShape::disk) return sdf::xDisk(o - e.center, v, e.normal, e.radius, t_max);
    return sdf::xSphere(o - e.center, v, e.radius, t_max);
}

Vec3 emitter_normal(const Emitter& e, Vec3 p) {
    if (e.shape == EmitterShape::rect) return sdf::nRect(e.normal);
    if (e.shape == EmitterShape::disk) return sdf::nDisk(e.normal);
    return sdf::nSphere(p - e.center, e.radius);
}

// Objects in file order, then emitters; a tie keeps the earlier (as the generated scene_nearest).
// march_only: the march's field, without what is intersected exactly (INFINITY when empty).
float nearest_surface(const Scene& scene, Vec3 p, int* nearest, bool march_only = false) {
    float d = INFINITY;
    int k = 0, index = 0;
    bool first = true;
    auto consider = [&](float e) {
        if (first || e < d) {
            first = false;
            d = e;
            k = index;
        }
        ++index;
    };
    for (const Object& o : scene.objects) {
        if (march_only && object_is_exact(scene, o)) ++index;
        else consider(shape_distance(o.shape, p));
    }
    for (const Emitter& e : scene.emitters) {
        if (march_only && emitter_is_exact(scene, e)) ++index;
        else consider(emitter_distance(e, p));
    }
    *nearest = k;
    return d;
}

}  // namespace

float shape_distance(const Node& node, Vec3 p) {
    if (node.children.empty()) return primitive_distance(node.kind, p);
    if (auto* c = std::get_if<Combine>(&node.kind)) {
        float d = shape_distance(node.children[0], p);
        for (size_t k = 1; k < node.children.size(); ++k) d = combine(c->op, d, shape_distance(node.children[k], p), c->radius);
        return d;
    }
    const Node& child = node.children[0];
    if (auto* t = std::get_if<Translate>(&node.kind)) return shape_distance(child, p - t->offset);
    if (auto* r = std::get_if<Rotate>(&node.kind)) return shape_distance(child, apply_rotation(r->rotation, p, true));
    if (auto* s = std::get_if<Scale>(&node.kind)) return s->factor * shape_distance(child, p / s->factor);
    if (auto* r = std::get_if<Repeat>(&node.kind)) return shape_distance(child, sdf::pMod3(p, r->period));
    if (auto* r = std::get_if<RepeatLimited>(&node.kind))
        return shape_distance(child, sdf::pModInterval3(p, r->period, r->count_min, r->count_max));
    if (auto* d = std::get_if<Displace>(&node.kind)) return sdf::fOpDisplaceSine(shape_distance(child, p), p, d->amplitude, d->frequency);
    return 0.0f;
}

float scene_distance(const Scene& scene, Vec3 p) {
    int k;
    return nearest_surface(scene, p, &k);
}

float scene_distance_material(const Scene& scene, Vec3 p, int* material) {
    int k;
    float d = nearest_surface(scene, p, &k);
    int objects = int(scene.objects.size());
    *material = k < objects ? scene.objects[size_t(k)].material : scene.emitters[size_t(k - objects)].material;
    return d;
}

float scene_march_distance(const Scene& scene, Vec3 p) {
    int k;
    return nearest_surface(scene, p, &k, true);
}

float scene_exact_hit(const Scene& scene, Vec3 o, Vec3 v, float t_max) {
    float t = EXACT_MISS;
    for (const Object& object : scene.objects)
        if (object_is_exact(scene, object)) t = std::fmin(t, shape_exact_hit(object.shape, o, v, std::fmin(t, t_max)));
    for (const Emitter& e : scene.emitters)
        if (emitter_is_exact(scene, e)) t = std::fmin(t, emitter_exact_hit(e, o, v, std::fmin(t, t_max)));
    return t;
}

int scene_surface(const Scene& scene, Vec3 p, int* slot, Vec3* n) {
    int k;
    nearest_surface(scene, p, &k);
    int objects = int(scene.objects.size());
    *slot = k < objects ? scene.objects[size_t(k)].material : scene.emitters[size_t(k - objects)].material;
    if (k < objects ? !object_is_exact(scene, scene.objects[size_t(k)]) : !emitter_is_exact(scene, scene.emitters[size_t(k - objects)])) return 0;
    return scene_analytic_normal(scene, p, n);
}

int scene_analytic_normal(const Scene& scene, Vec3 p, Vec3* n) {
    int k;
    nearest_surface(scene, p, &k);
    int objects = int(scene.objects.size());
    if (k >= objects) {
        *n = emitter_normal(scene.emitters[size_t(k - objects)], p);
        return 1;
    }
    return shape_normal(scene.objects[size_t(k)].shape, p, n) ? 1 : 0;
}

}  // namespace lab::scene
