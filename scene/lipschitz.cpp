#include "scene/lipschitz.hpp"

#include <cmath>
#include <limits>

#include "scene/json_fields.hpp"
#include "sdf/sdf.hpp"

namespace lab::scene {
namespace {

constexpr float kUnbounded = std::numeric_limits<float>::infinity();
const char* const kAxisNames[3] = {"x", "y", "z"};

ShapeAnalysis primitive(Vec3 extent, std::array<bool, 3> symmetric) {
    ShapeAnalysis a{1.0f, extent, symmetric, {}};
    a.box_half = extent;  // about the primitive's own centre, the origin
    return a;
}

// The centred box [lo, hi] as centre and half extents; an infinite axis gets centre 0.
void set_box(Vec3 lo, Vec3 hi, ShapeAnalysis* a) {
    for (int i = 0; i < 3; ++i) {
        bool bounded = std::isfinite(lo[i]) && std::isfinite(hi[i]);
        a->box_center[i] = bounded ? 0.5f * (lo[i] + hi[i]) : 0.0f;
        a->box_half[i] = bounded ? 0.5f * (hi[i] - lo[i]) : kUnbounded;
    }
}

Vec3 box_lo(const ShapeAnalysis& a) { return a.box_center - a.box_half; }
Vec3 box_hi(const ShapeAnalysis& a) { return a.box_center + a.box_half; }

// Fewer unbounded axes first, then the smaller volume: which of two boxes an intersection keeps.
bool smaller_box(const ShapeAnalysis& a, const ShapeAnalysis& b) {
    int unbounded_a = 0, unbounded_b = 0;
    double volume_a = 1.0, volume_b = 1.0;
    for (int i = 0; i < 3; ++i) {
        if (std::isfinite(a.box_half[i])) volume_a *= a.box_half[i]; else ++unbounded_a;
        if (std::isfinite(b.box_half[i])) volume_b *= b.box_half[i]; else ++unbounded_b;
    }
    return unbounded_a != unbounded_b ? unbounded_a < unbounded_b : volume_a < volume_b;
}

// Primitives are exact distances (sdf/primitives/), so f(p) = dist(p, solid) >= dist(p, B) for any
// box B holding the solid.
ShapeAnalysis analyse_primitive(const NodeKind& kind) {
    constexpr std::array<bool, 3> all = {true, true, true};
    if (auto* s = std::get_if<Sphere>(&kind)) return primitive(Vec3(s->radius), all);
    if (auto* p = std::get_if<Plane>(&kind))  // a half-space: unbounded whatever its normal
        return primitive(Vec3(kUnbounded), {p->normal.x == 0.0f, p->normal.y == 0.0f, p->normal.z == 0.0f});
    if (auto* b = std::get_if<Box>(&kind)) return primitive(b->half_size, all);
    if (auto* b = std::get_if<RoundBox>(&kind)) return primitive(b->half_size, all);
    if (auto* t = std::get_if<Torus>(&kind)) {
        float outer = t->major_radius + t->minor_radius;
        return primitive(Vec3(outer, t->minor_radius, outer), all);
    }
    if (auto* c = std::get_if<Cylinder>(&kind)) return primitive(Vec3(c->radius, c->half_height, c->radius), all);
    if (auto* c = std::get_if<Capsule>(&kind)) return primitive(Vec3(c->radius, c->half_height + c->radius, c->radius), all);
    if (auto* c = std::get_if<Cone>(&kind)) return primitive(Vec3(c->radius, c->height, c->radius), {true, false, true});
    return {};
}

// The box about the origin holding R B: extent_i = sum_j |R_ij| b_j (zero entries skipped, so an
// infinite extent does not turn into 0 * inf).
Vec3 rotated_extent(const glm::mat3& r, Vec3 b) {
    Vec3 out(0.0f);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (r[j][i] != 0.0f) out[i] += std::fabs(r[j][i]) * b[j];  // glm: r[column][row]
    return out;
}

// The field g(p) = f(R^T p) is symmetric about the world plane p_i = 0 when R^T e_i, the normal of
// that mirror in the child's frame, is a coordinate axis about which f is symmetric:
// g(S_i p) = f(R^T S_i p) = f(S_v R^T p) with v = R^T e_i.
std::array<bool, 3> rotated_symmetry(const glm::mat3& r, const std::array<bool, 3>& child) {
    std::array<bool, 3> out{false, false, false};
    for (int i = 0; i < 3; ++i) {
        Vec3 v(r[0][i], r[1][i], r[2][i]);  // R^T e_i = row i of R (glm: r[column][row])
        for (int j = 0; j < 3; ++j) {
            bool axis_j = std::fabs(std::fabs(v[j]) - 1.0f) < 1e-6f && std::fabs(v[(j + 1) % 3]) < 1e-6f &&
                          std::fabs(v[(j + 2) % 3]) < 1e-6f;
            if (axis_j && child[j]) out[i] = true;
        }
    }
    return out;
}

// Repetition keeps the child's bound when, along every repeated axis, the child fits in its cell
// and is mirror-symmetric about the cell's mid-plane (sdf/domain/mod3.h); otherwise the field jumps
// at the cell faces.
void check_repetition(const Node& node, Vec3 period, std::array<bool, 3> repeated, const ShapeAnalysis& child, ShapeAnalysis* out) {
    for (int i = 0; i < 3; ++i) {
        if (!repeated[i]) continue;
        std::string axis = kAxisNames[i];
        if (!(child.extent[i] <= 0.5f * period[i]))
            out->broken.push_back(node.path + ": the child (extent " + format_number(child.extent[i]) + " along " + axis +
                                  ") does not fit in its cell (half the period is " + format_number(0.5f * period[i]) +
                                  "): the copies are cut at the cell faces");
        if (!child.mirror_symmetric[i])
            out->broken.push_back(node.path + ": the child is not mirror-symmetric about its cell's mid-plane " + axis +
                                  " = 0: the field jumps at the cell faces (a neighbouring copy can be nearer)");
    }
}

std::array<bool, 3> symmetric_and(const std::array<bool, 3>& a, const std::array<bool, 3>& b) {
    return {a[0] && b[0], a[1] && b[1], a[2] && b[2]};
}

bool inside_box(Vec3 a, Vec3 b) { return a.x <= b.x && a.y <= b.y && a.z <= b.z; }

ShapeAnalysis analyse_combine(const Combine& c, const std::vector<ShapeAnalysis>& children) {
    ShapeAnalysis out = children[0];
    for (size_t k = 1; k < children.size(); ++k) {
        const ShapeAnalysis& b = children[k];
        out.mirror_symmetric = symmetric_and(out.mirror_symmetric, b.mirror_symmetric);
        out.broken.insert(out.broken.end(), b.broken.begin(), b.broken.end());
        switch (c.op) {
        case Combinator::union_:
        case Combinator::intersection:
        case Combinator::subtraction:
        case Combinator::smooth_union: out.lipschitz = sdf::lipschitz_union(out.lipschitz, b.lipschitz); break;
        case Combinator::round_union:
        case Combinator::round_intersection:
        case Combinator::round_subtraction: out.lipschitz = sdf::lipschitz_round(out.lipschitz, b.lipschitz); break;
        case Combinator::chamfer_union:
        case Combinator::chamfer_intersection:
        case Combinator::chamfer_subtraction: out.lipschitz = sdf::lipschitz_chamfer(out.lipschitz, b.lipschitz); break;
        }
        // The box: a union holds both operands' boxes, grown by how far the blend reaches outwards
        // (smooth: f >= min(a, b) - k/4, sdf/combinators/union_smooth.h; round and chamfer equal
        // min(a, b) where both are >= r). Every intersection variant is >= each operand outside that
        // operand's box, so either operand's box will do (the smaller one is kept); a subtraction
        // variant is >= its first operand there.
        float grow = c.op == Combinator::smooth_union ? 0.25f * c.radius : (c.op == Combinator::union_ ? 0.0f : c.radius);
        switch (c.op) {
        case Combinator::union_:
        case Combinator::smooth_union:
        case Combinator::round_union:
        case Combinator::chamfer_union:
            out.extent = glm::max(out.extent, b.extent) + Vec3(grow);
            set_box(glm::min(box_lo(out), box_lo(b)) - Vec3(grow), glm::max(box_hi(out), box_hi(b)) + Vec3(grow), &out);
            break;
        case Combinator::intersection:
        case Combinator::round_intersection:
        case Combinator::chamfer_intersection:
            if (inside_box(b.extent, out.extent)) out.extent = b.extent;
            if (smaller_box(b, out)) {
                out.box_center = b.box_center;
                out.box_half = b.box_half;
            }
            break;
        case Combinator::subtraction:
        case Combinator::round_subtraction:
        case Combinator::chamfer_subtraction: break;
        }
    }
    return out;
}

}  // namespace

ShapeAnalysis analyse_shape(const Node& node) {
    if (node.children.empty()) return analyse_primitive(node.kind);
    std::vector<ShapeAnalysis> children;
    for (const Node& c : node.children) children.push_back(analyse_shape(c));
    if (auto* c = std::get_if<Combine>(&node.kind)) return analyse_combine(*c, children);

    ShapeAnalysis out = children[0];
    if (auto* t = std::get_if<Translate>(&node.kind)) {
        out.extent += glm::abs(t->offset);
        for (int i = 0; i < 3; ++i)
            if (std::isfinite(out.box_half[i])) out.box_center[i] += t->offset[i];
        for (int i = 0; i < 3; ++i) out.mirror_symmetric[i] = out.mirror_symmetric[i] && t->offset[i] == 0.0f;
    } else if (auto* r = std::get_if<Rotate>(&node.kind)) {
        out.extent = rotated_extent(r->rotation, out.extent);
        // R c holds the box's rotated centre; an axis the rotation mixes an unbounded one into is unbounded
        Vec3 center = r->rotation * out.box_center, half = rotated_extent(r->rotation, out.box_half);
        set_box(center - half, center + half, &out);
        out.mirror_symmetric = rotated_symmetry(r->rotation, out.mirror_symmetric);
    } else if (auto* s = std::get_if<Scale>(&node.kind)) {
        out.extent *= s->factor;  // s f(p / s) keeps f's gradient (at p / s), so its bound too
        set_box(s->factor * box_lo(out), s->factor * box_hi(out), &out);
    } else if (auto* d = std::get_if<Displace>(&node.kind)) {
        out.lipschitz = sdf::lipschitz_displace_sine(out.lipschitz, d->amplitude, d->frequency);
        out.extent += Vec3(d->amplitude);              // f + A s >= f - A
        set_box(box_lo(out) - Vec3(d->amplitude), box_hi(out) + Vec3(d->amplitude), &out);
        out.mirror_symmetric = {false, false, false};  // the sine product is odd in every coordinate
    } else if (auto* r = std::get_if<Repeat>(&node.kind)) {
        std::array<bool, 3> repeated = {r->period.x > 0.0f, r->period.y > 0.0f, r->period.z > 0.0f};
        check_repetition(node, r->period, repeated, children[0], &out);
        for (int i = 0; i < 3; ++i)
            if (repeated[i]) out.extent[i] = out.box_half[i] = kUnbounded, out.box_center[i] = 0.0f;
        // the cell map is odd in each coordinate, so the child's symmetries survive
    } else if (auto* r = std::get_if<RepeatLimited>(&node.kind)) {
        std::array<bool, 3> repeated{};
        for (int i = 0; i < 3; ++i) {
            repeated[i] = r->period[i] > 0.0f && r->count_min[i] < r->count_max[i];
            // the farthest copy's offset: each copy is the child translated by period * k
            out.extent[i] += r->period[i] * std::fmax(std::fabs(r->count_min[i]), std::fabs(r->count_max[i]));
            // copies at period * k for k in [count_min, count_max]
            if (std::isfinite(out.box_half[i])) {
                out.box_center[i] += 0.5f * r->period[i] * (r->count_min[i] + r->count_max[i]);
                out.box_half[i] += 0.5f * r->period[i] * (r->count_max[i] - r->count_min[i]);
            }
            out.mirror_symmetric[i] = out.mirror_symmetric[i] && (r->period[i] == 0.0f || r->count_min[i] == -r->count_max[i]);
        }
        check_repetition(node, r->period, repeated, children[0], &out);
    }
    return out;
}

SceneAnalysis analyse_scene(const Scene& scene) {
    SceneAnalysis result;
    std::string steepest;
    for (const Object& object : scene.objects) {
        ShapeAnalysis a = analyse_shape(object.shape);
        if (a.lipschitz > result.lipschitz) steepest = "object \"" + object.name + "\"";
        result.lipschitz = std::fmax(result.lipschitz, a.lipschitz);
        for (const std::string& reason : a.broken) {
            result.is_distance_bound = false;
            result.warnings.push_back(scene.file + ": " + reason + "; the field is not a distance bound and rays may step through surfaces");
        }
    }
    // Emitters are spheres, rects and disks with exact distances: bound 1, which the maximum includes.
    if (result.lipschitz > 1.0f)
        result.warnings.push_back(scene.file + ": the distance field's Lipschitz bound is " + format_number(result.lipschitz) + " (" +
                                  steepest + "), above 1: sphere tracing divides distances by it, so rays take more steps");
    return result;
}

}  // namespace lab::scene
