#include "scene/object_functions.hpp"

#include <cmath>
#include <optional>

#include "scene/rotation.hpp"
#include "scene/source_literals.hpp"

namespace lab::scene {
namespace {

// A primitive's sdf/ header, its function name stem (fX / nX) and its arguments after p.
struct PrimitiveCall {
    const char* header;
    const char* stem;
    std::string arguments;             // for nX(float3 p, ...)
    std::string component_arguments;   // for fX_xyz(x, y, z, ...): vectors as three floats
};

std::optional<PrimitiveCall> primitive_call(const NodeKind& kind) {
    auto f = [](float v) { return float_literal(v); };
    auto scalars = [](const char* header, const char* stem, const std::string& a) { return PrimitiveCall{header, stem, a, a}; };
    if (auto* s = std::get_if<Sphere>(&kind)) return scalars("sdf/primitives/sphere.h", "Sphere", f(s->radius));
    if (auto* p = std::get_if<Plane>(&kind))
        return PrimitiveCall{"sdf/primitives/plane.h", "Plane", vec3_literal(p->normal) + ", " + f(p->offset),
                             components_literal(p->normal) + ", " + f(p->offset)};
    if (auto* b = std::get_if<Box>(&kind))
        return PrimitiveCall{"sdf/primitives/box.h", "Box", vec3_literal(b->half_size), components_literal(b->half_size)};
    if (auto* b = std::get_if<RoundBox>(&kind))
        return PrimitiveCall{"sdf/primitives/round_box.h", "RoundBox", vec3_literal(b->half_size) + ", " + f(b->radius),
                             components_literal(b->half_size) + ", " + f(b->radius)};
    if (auto* t = std::get_if<Torus>(&kind)) return scalars("sdf/primitives/torus.h", "Torus", f(t->major_radius) + ", " + f(t->minor_radius));
    if (auto* c = std::get_if<Cylinder>(&kind)) return scalars("sdf/primitives/cylinder.h", "Cylinder", f(c->radius) + ", " + f(c->half_height));
    if (auto* c = std::get_if<Capsule>(&kind)) return scalars("sdf/primitives/capsule.h", "Capsule", f(c->radius) + ", " + f(c->half_height));
    if (auto* c = std::get_if<Cone>(&kind)) return scalars("sdf/primitives/cone.h", "Cone", f(c->radius) + ", " + f(c->height));
    return std::nullopt;
}

struct CombinatorCall {
    const char* header;
    const char* function;
};

CombinatorCall combinator_call(Combinator op) {
    switch (op) {
    case Combinator::union_: return {"sdf/combinators/union.h", "fOpUnion"};
    case Combinator::intersection: return {"sdf/combinators/intersection.h", "fOpIntersection"};
    case Combinator::subtraction: return {"sdf/combinators/subtraction.h", "fOpSubtraction"};
    case Combinator::smooth_union: return {"sdf/combinators/union_smooth.h", "fOpUnionSmooth"};
    case Combinator::round_union: return {"sdf/combinators/union_round.h", "fOpUnionRound"};
    case Combinator::round_intersection: return {"sdf/combinators/intersection_round.h", "fOpIntersectionRound"};
    case Combinator::round_subtraction: return {"sdf/combinators/subtraction_round.h", "fOpSubtractionRound"};
    case Combinator::chamfer_union: return {"sdf/combinators/union_chamfer.h", "fOpUnionChamfer"};
    case Combinator::chamfer_intersection: return {"sdf/combinators/intersection_chamfer.h", "fOpIntersectionChamfer"};
    case Combinator::chamfer_subtraction: return {"sdf/combinators/subtraction_chamfer.h", "fOpSubtractionChamfer"};
    }
    return {"", ""};
}

bool blended(Combinator op) { return op != Combinator::union_ && op != Combinator::intersection && op != Combinator::subtraction; }

// Component i of R^T p or R n written out as rotation_terms() says, so the host interpreter rounds
// alike; v.x or vx as `component` says.
std::string rotation_component(const glm::mat3& r, const std::string& v, bool inverse, int i, const char* const component[3]) {
    std::string sum;
    for (const auto& [c, j] : rotation_terms(r, i, inverse)) {
        // a + (-c) x equals a - c x exactly, and 1 x equals x: the same arithmetic, easier to read
        std::string operand = v + component[j];
        std::string magnitude = std::fabs(c) == 1.0f ? operand : float_literal(std::fabs(c)) + " * " + operand;
        if (sum.empty())
            sum = (c < 0.0f ? "-" : "") + magnitude;
        else
            sum += (c < 0.0f ? " - " : " + ") + magnitude;
    }
    return sum.empty() ? std::string("0.0f") : sum;
}

const char* const kMemberComponents[3] = {".x", ".y", ".z"};
const char* const kScalarComponents[3] = {"x", "y", "z"};

std::string rotation_expression(const glm::mat3& r, const std::string& v, bool inverse) {
    std::string out = "make_float3(";
    for (int i = 0; i < 3; ++i) out += (i ? ", " : "") + rotation_component(r, v, inverse, i, kMemberComponents);
    return out + ")";
}

}  // namespace

std::string emit_distance(const Node& node, const std::string& p, FunctionWriter* w) {
    if (auto call = primitive_call(node.kind)) {
        w->use(call->header);
        return w->distance(std::string("f") + call->stem + "_xyz(" + component_names(p) + ", " + call->component_arguments + ")");
    }
    if (auto* c = std::get_if<Combine>(&node.kind)) {
        CombinatorCall call = combinator_call(c->op);
        w->use(call.header);
        std::string radius = blended(c->op) ? ", " + float_literal(c->radius) : "";
        std::string d = emit_distance(node.children[0], p, w);
        for (size_t k = 1; k < node.children.size(); ++k) {
            std::string e = emit_distance(node.children[k], p, w);
            d = w->distance(std::string(call.function) + "(" + d + ", " + e + radius + ")");
        }
        return d;
    }
    const Node& child = node.children[0];
    auto each = [&](auto component) { return w->point_components(component(0), component(1), component(2)); };
    auto at = [&](int i) { return p + kScalarComponents[i]; };
    if (auto* t = std::get_if<Translate>(&node.kind))
        return emit_distance(child, each([&](int i) { return at(i) + " - " + float_literal(t->offset[i]); }), w);
    if (auto* r = std::get_if<Rotate>(&node.kind))
        return emit_distance(child, each([&](int i) { return rotation_component(r->rotation, p, true, i, kScalarComponents); }), w);
    if (auto* s = std::get_if<Scale>(&node.kind)) {
        std::string d = emit_distance(child, each([&](int i) { return at(i) + " / " + float_literal(s->factor); }), w);
        return w->distance(float_literal(s->factor) + " * " + d);
    }
    if (auto* r = std::get_if<Repeat>(&node.kind)) {
        w->use("sdf/domain/mod3.h");
        return emit_distance(child, each([&](int i) { return "pMod1(" + at(i) + ", " + float_literal(r->period[i]) + ")"; }), w);
    }
    if (auto* r = std::get_if<RepeatLimited>(&node.kind)) {
        w->use("sdf/domain/mod_interval3.h");
        return emit_distance(child, each([&](int i) {
                                 return "pModInterval1(" + at(i) + ", " + float_literal(r->period[i]) + ", " + float_literal(r->count_min[i]) +
                                        ", " + float_literal(r->count_max[i]) + ")";
                             }),
                             w);
    }
    if (auto* d = std::get_if<Displace>(&node.kind)) {
        w->use("sdf/combinators/displace_sine.h");
        std::string inner = emit_distance(child, p, w);
        return w->distance("fOpDisplaceSine_xyz(" + inner + ", " + component_names(p) + ", " + float_literal(d->amplitude) + ", " +
                           float_literal(d->frequency) + ")");
    }
    return "0.0f";
}

bool has_analytic_normal(const Node& node) {
    if (primitive_call(node.kind)) return true;
    if (std::holds_alternative<Translate>(node.kind) || std::holds_alternative<Rotate>(node.kind) ||
        std::holds_alternative<Scale>(node.kind))
        return has_analytic_normal(node.children[0]);
    return false;
}

std::string emit_normal(const Node& node, const std::string& p, FunctionWriter* w) {
    if (auto call = primitive_call(node.kind)) return w->normal(std::string("n") + call->stem + "(" + p + ", " + call->arguments + ")");
    const Node& child = node.children[0];
    if (auto* t = std::get_if<Translate>(&node.kind)) return emit_normal(child, w->point(p + " - " + vec3_literal(t->offset)), w);
    if (auto* r = std::get_if<Rotate>(&node.kind)) {
        std::string n = emit_normal(child, w->point(rotation_expression(r->rotation, p, true)), w);
        return w->normal(rotation_expression(r->rotation, n, false));
    }
    auto* s = std::get_if<Scale>(&node.kind);
    return emit_normal(child, w->point(p + " / " + float_literal(s->factor)), w);
}

std::string emit_exact_hit(const Node& node, const std::string& o, const std::string& v, const std::string& t_max, FunctionWriter* w) {
    if (auto call = primitive_call(node.kind)) {
        std::string header = call->header;
        w->use(header.replace(header.find("primitives"), std::string("primitives").size(), "exact"));
        return std::string("x") + call->stem + "(" + o + ", " + v + ", " + call->arguments + ", " + t_max + ")";
    }
    const Node& child = node.children[0];
    if (auto* t = std::get_if<Translate>(&node.kind)) return emit_exact_hit(child, w->point(o + " - " + vec3_literal(t->offset)), v, t_max, w);
    if (auto* r = std::get_if<Rotate>(&node.kind)) {
        std::string local_o = w->point(rotation_expression(r->rotation, o, true));
        return emit_exact_hit(child, local_o, w->point(rotation_expression(r->rotation, v, true)), t_max, w);
    }
    auto* s = std::get_if<Scale>(&node.kind);
    std::string local_o = w->point(o + " / " + float_literal(s->factor));
    std::string hit = emit_exact_hit(child, local_o, v, w->scalar(t_max + " / " + float_literal(s->factor)), w);
    return float_literal(s->factor) + " * (" + hit + ")";
}

bool has_exact_hit_lanes(const Node& node) {
    if (primitive_call(node.kind)) return !std::holds_alternative<Torus>(node.kind);
    if (std::holds_alternative<Translate>(node.kind) || std::holds_alternative<Rotate>(node.kind) ||
        std::holds_alternative<Scale>(node.kind))
        return has_exact_hit_lanes(node.children[0]);
    return false;
}

std::string emit_exact_hit_lanes(const Node& node, const std::string& o, const std::string& v, const std::string& t_max, FunctionWriter* w) {
    auto at = [](const std::string& p, int i) { return p + kScalarComponents[i]; };
    if (auto call = primitive_call(node.kind)) {
        std::string header = call->header;
        w->use(header.replace(header.find("primitives"), std::string("primitives").size(), "exact"));
        return std::string("x") + call->stem + "_lanes(" + component_names(o) + ", " + component_names(v) + ", " + call->component_arguments +
               ", " + t_max + ")";
    }
    const Node& child = node.children[0];
    auto each = [&](auto component) { return w->point_components(component(0), component(1), component(2)); };
    if (auto* t = std::get_if<Translate>(&node.kind))
        return emit_exact_hit_lanes(child, each([&](int i) { return at(o, i) + " - " + float_literal(t->offset[i]); }), v, t_max, w);
    if (auto* r = std::get_if<Rotate>(&node.kind)) {
        std::string local_o = each([&](int i) { return rotation_component(r->rotation, o, true, i, kScalarComponents); });
        return emit_exact_hit_lanes(child, local_o, each([&](int i) { return rotation_component(r->rotation, v, true, i, kScalarComponents); }), t_max,
                                    w);
    }
    auto* s = std::get_if<Scale>(&node.kind);
    std::string local_o = each([&](int i) { return at(o, i) + " / " + float_literal(s->factor); });
    std::string hit = emit_exact_hit_lanes(child, local_o, v, w->lane_scalar(t_max + " / " + float_literal(s->factor)), w);
    return float_literal(s->factor) + " * (" + hit + ")";
}

float evaluation_cost(const Node& node) {
    if (primitive_call(node.kind)) return std::holds_alternative<Cone>(node.kind) ? 2.0f : 1.0f;
    float cost = 0.0f;
    for (const Node& child : node.children) cost += evaluation_cost(child);
    if (std::holds_alternative<Translate>(node.kind) || std::holds_alternative<Scale>(node.kind)) return cost;
    if (std::holds_alternative<Displace>(node.kind)) return cost + 3.0f;  // three sines
    return cost + 1.0f;                                                    // a rotation, a repetition, a blend
}

}  // namespace lab::scene
