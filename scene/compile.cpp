#include "scene/compile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "brdf/host/features.hpp"
#include "common/input_error.hpp"
#include "scene/json_fields.hpp"
#include "scene/lipschitz.hpp"
#include "scene/object_tree.hpp"
#include "scene/rotation.hpp"

namespace lab::scene {
namespace {

// "x, y, z": a vector as the three arguments of a component form (sdf/, fX_xyz).
std::string components_literal(Vec3 v) { return float_literal(v.x) + ", " + float_literal(v.y) + ", " + float_literal(v.z); }

std::string vec3_literal(Vec3 v) { return "make_float3(" + components_literal(v) + ")"; }

// The distance functions take the point as three SDF_FLOATs ("px, py, pz" for the point named "p"),
// one point or, under SDF_LANES, a packet of eight (docs/sdf.md, "Component forms and packets").
// Normals keep float3.
std::string components(const std::string& p) { return p + "x, " + p + "y, " + p + "z"; }

// The components of p - c: "px - cx, py - cy, pz - cz".
std::string offset_components(Vec3 c) {
    return "px - " + float_literal(c.x) + ", py - " + float_literal(c.y) + ", pz - " + float_literal(c.z);
}

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

// The body of one generated function: numbered locals, one statement each, and the headers used.
class FunctionWriter {
public:
    explicit FunctionWriter(std::set<std::string>* headers) : headers_(headers) {}

    std::string point(const std::string& expression) { return local("float3", "p", expression); }
    // A point as three float locals pNx, pNy, pNz (one statement); returns "pN".
    std::string point_components(const std::string& x, const std::string& y, const std::string& z) {
        std::string name = "p" + std::to_string(next_++);
        body_ += "    SDF_FLOAT " + name + "x = " + x + ", " + name + "y = " + y + ", " + name + "z = " + z + ";\n";
        return name;
    }
    std::string distance(const std::string& expression) { return local("SDF_FLOAT", "d", expression); }
    std::string normal(const std::string& expression) { return local("float3", "n", expression); }
    void use(const std::string& header) { headers_->insert(header); }
    const std::string& body() const { return body_; }

private:
    std::string local(const char* type, const char* prefix, const std::string& expression) {
        std::string name = prefix + std::to_string(next_++);
        body_ += std::string("    ") + type + " " + name + " = " + expression + ";\n";
        return name;
    }
    std::set<std::string>* headers_;
    std::string body_;
    int next_ = 1;
};

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

// The distance of `node` at the point whose components are named px, py, pz (p the stem).
std::string emit_distance(const Node& node, const std::string& p, FunctionWriter* w) {
    if (auto call = primitive_call(node.kind)) {
        w->use(call->header);
        return w->distance(std::string("f") + call->stem + "_xyz(" + components(p) + ", " + call->component_arguments + ")");
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
        return w->distance("fOpDisplaceSine_xyz(" + inner + ", " + components(p) + ", " + float_literal(d->amplitude) + ", " +
                           float_literal(d->frequency) + ")");
    }
    return "0.0f";
}

// A primitive under rigid transforms and uniform scales only: its normal is the primitive's
// analytic one (nX) turned back by the rotations (translation and uniform scale leave it).
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

// A rough cost of evaluating the node, in primitive evaluations: where an object costs more than its
// box test (about one and a half primitives), the test pays when it skips the object.
float evaluation_cost(const Node& node) {
    if (primitive_call(node.kind)) return std::holds_alternative<Cone>(node.kind) ? 2.0f : 1.0f;
    float cost = 0.0f;
    for (const Node& child : node.children) cost += evaluation_cost(child);
    if (std::holds_alternative<Translate>(node.kind) || std::holds_alternative<Scale>(node.kind)) return cost;
    if (std::holds_alternative<Displace>(node.kind)) return cost + 3.0f;  // three sines
    return cost + 1.0f;                                                    // a rotation, a repetition, a blend
}

constexpr float kBoundedObjectCost = 2.5f;

// Object trees of at least this many objects start with the nearer-first guess (NearestWriter).
constexpr size_t kGuessMinObjects = 16;

// Whether an object is worth a box test of its own: it costs more than the test, and its box
// bounds it along two axes or more (with f >= dist(p, box), which a broken repetition does not
// keep). A box bounded along one axis is a slab that most rays of a scene cross: the repetition
// scene's colonnade, an endless row of columns, would have a test that skips nothing (3.00 distance
// evaluations per step with and without it) and costs 13-17 % of its paths/s (bench objects).
bool worth_bounding(const Object& object, const ShapeAnalysis& a) {
    int bounded = int(std::isfinite(a.box_half.x)) + int(std::isfinite(a.box_half.y)) + int(std::isfinite(a.box_half.z));
    return bounded >= 2 && a.broken.empty() && evaluation_cost(object.shape) >= kBoundedObjectCost;
}

// The body of scene_nearest: the nearest object or emitter (index: objects in file order, then
// emitters) and its distance. Unbounded and large objects come first, then the others through the
// object tree (scene/object_tree.hpp), then large objects with a box test of their own, then the
// emitters; a tie goes to the lower index whatever the order, and a box test skips only what is
// strictly farther than the nearest so far, so the result is the one of evaluating everything in
// file order.
class NearestWriter {
public:
    // packet: the body of the packet kernels' scene_distance_xyz (SDF_LANES points at once): the
    // nearest distance only; a box test skips a group only when it may for every active lane (the
    // march's running lanes: a lane that is done would keep its own object's group in every step),
    // and the guess goes down the child nearer to the active lanes on the whole.
    NearestWriter(const Scene& scene, bool object_bounds, bool packet, std::set<std::string>* headers) : headers_(headers), packet_(packet) {
        std::vector<ObjectBox> boxes;
        std::vector<ShapeAnalysis> analyses;
        for (const Object& object : scene.objects) analyses.push_back(analyse_shape(object.shape));
        // An object whose box spans much of the scene (a wall, a floor slab) is near every point:
        // a group holding it would rarely be skipped, so it goes with the unbounded ones.
        Vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
        auto finite = [](const ShapeAnalysis& a) {
            return std::isfinite(a.box_half.x) && std::isfinite(a.box_half.y) && std::isfinite(a.box_half.z) && a.broken.empty();
        };
        for (const ShapeAnalysis& a : analyses)
            if (finite(a)) lo = glm::min(lo, a.box_center - a.box_half), hi = glm::max(hi, a.box_center + a.box_half);
        float large = 0.5f * glm::length(hi - lo);
        std::vector<int> last;  // large objects with a box test of their own
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            const ShapeAnalysis& a = analyses[i];
            bool own = object_bounds && worth_bounding(scene.objects[i], a);
            if (object_bounds && finite(a) && 2.0f * glm::length(a.box_half) <= large)
                boxes.push_back(ObjectBox{int(i), a.box_center - a.box_half, a.box_center + a.box_half, own});
            else if (own)
                last.push_back(int(i));
            else
                object(int(i), nullptr, "    ");
        }
        std::vector<ObjectTreeNode> tree = build_object_tree(boxes);
        for (const ObjectBox& box : boxes) own_test_[box.object] = box.own_test ? analyses[size_t(box.object)] : std::optional<ShapeAnalysis>();
        if (!tree.empty()) traversal(tree);
        // tested against the nearest of everything else: first, its test could never skip (the
        // test model's body, 3.00 distance evaluations per step with the ground after it)
        for (int i : last) object(i, &analyses[size_t(i)], "    ");
    }

    // A surface at distance `expression`, index `index`.
    void candidate(const std::string& expression, int index, const std::string& indent) {
        if (packet_) {
            body_ << indent << "d = fmin(d, " << expression << ");\n";
            return;
        }
        body_ << indent << "e = " << expression << ";\n"
              << indent << "SCENE_COUNT_EVALUATION;\n"
              << indent << "if (e < d || (e == d && " << index << " < k)) { d = e; k = " << index << "; }\n";
    }
    const std::string body() const { return body_.str(); }
    int box_tests() const { return box_tests_; }

private:
    void object(int i, const ShapeAnalysis* own_test, const std::string& indent) {
        std::string call = "scene_object_" + std::to_string(i) + "(px, py, pz)";
        if (!own_test) return candidate(call, i, indent);
        open_test(own_test->box_center, own_test->box_half, indent);
        candidate(call, i, indent + "    ");
        body_ << indent << "}\n";
    }

    static std::string box_distance(const ObjectTreeNode& n) {
        return box_distance(0.5f * (n.lo + n.hi), 0.5f * (n.hi - n.lo));
    }

    // fBox at p - center, in components.
    static std::string box_distance(Vec3 center, Vec3 half) {
        return "fBox_xyz(" + offset_components(center) + ", " + components_literal(half) + ")";
    }

    // The tree in two passes, both straight-line code with literal boxes (a loop over a stack and a
    // switch runs 8x slower on PoCL for 11x fewer evaluations). First a guess: down the nearer child
    // (by box distance) at every node to one object, evaluated, so that the boxes of the second pass
    // are tested against a small distance. Then every group in tree order, each guarded by its box
    // test, skipping the guessed object (variable g).
    void traversal(const std::vector<ObjectTreeNode>& tree) {
        // The guess's box tests pay on a large tree only: 1.95x paths/s on the 64-object grid, 0.92x
        // on the primitives scene (a tree of a few objects, 1.27 evaluations per step without it).
        if (tree.size() < 2 * kGuessMinObjects - 1) return node(tree, 0, "    ");
        guessed_ = true;
        open_test(0.5f * (tree[0].lo + tree[0].hi), 0.5f * (tree[0].hi - tree[0].lo), "    ");
        body_ << "        int g;\n        " << (packet_ ? "SDF_FLOAT" : "float") << " b_left, b_right; /* the guess */\n";
        guess(tree, 0, "        ");
        const ObjectTreeNode& root = tree[0];
        node(tree, root.left, "        ");
        node(tree, root.right, "        ");
        body_ << "    }\n";
    }

    void guess(const std::vector<ObjectTreeNode>& tree, int k, const std::string& indent) {
        const ObjectTreeNode& n = tree[size_t(k)];
        if (n.object >= 0) {
            body_ << indent << "g = " << n.object << ";\n";
            return candidate("scene_object_" + std::to_string(n.object) + "(px, py, pz)", n.object, indent);
        }
        // a packet takes one child for all its lanes: the one nearer in the sum over the active lanes
        body_ << indent << "b_left = " << box_distance(tree[size_t(n.left)]) << ";\n"
              << indent << "b_right = " << box_distance(tree[size_t(n.right)]) << ";\n"
              << indent
              << (packet_ ? "if (SDF_SUM(select((SDF_FLOAT)0.0f, b_left - b_right, active)) <= 0.0f) {\n" : "if (b_left <= b_right) {\n");
        guess(tree, n.left, indent + "    ");
        body_ << indent << "} else {\n";
        guess(tree, n.right, indent + "    ");
        body_ << indent << "}\n";
        box_tests_ += 2;
    }

    void node(const std::vector<ObjectTreeNode>& tree, int k, const std::string& indent) {
        const ObjectTreeNode& n = tree[size_t(k)];
        if (n.object >= 0) {
            const std::optional<ShapeAnalysis>& own = own_test_[n.object];
            if (!guessed_) return object(n.object, own ? &*own : nullptr, indent);
            body_ << indent << "if (g != " << n.object << ") {\n";
            object(n.object, own ? &*own : nullptr, indent + "    ");
            body_ << indent << "}\n";
            return;
        }
        open_test(0.5f * (n.lo + n.hi), 0.5f * (n.hi - n.lo), indent);
        node(tree, n.left, indent + "    ");
        node(tree, n.right, indent + "    ");
        body_ << indent << "}\n";
    }

    // "if the box is not strictly farther than the nearest surface so far {"; an unbounded axis gets
    // a half extent of 3e38, which fBox treats as infinite.
    void open_test(Vec3 center, Vec3 half, const std::string& indent) {
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(half[i])) half[i] = 3.0e38f;
        headers_->insert("sdf/primitives/box.h");
        body_ << indent << "b = " << box_distance(center, half) << ";\n"
              << indent << (packet_ ? "if (SDF_ANY(active && !(b > 0.0f && b > d))) {\n" : "if (!(b > 0.0f && b > d)) {\n");
        ++box_tests_;
    }

    std::set<std::string>* headers_;
    std::ostringstream body_;
    std::map<int, std::optional<ShapeAnalysis>> own_test_;
    int box_tests_ = 0;
    bool guessed_ = false;
    bool packet_;
};

std::string list_names(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

std::string generate_source(const Scene& scene, const SceneAnalysis& analysis, bool object_bounds) {
    std::set<std::string> headers;
    std::ostringstream functions;
    std::ostringstream normals, slot_cases, normal_cases;
    size_t index = 0;
    for (const Object& object : scene.objects) {
        FunctionWriter w(&headers);
        std::string d = emit_distance(object.shape, "p", &w);
        std::string name = "scene_object_" + std::to_string(index);
        functions << "/* object \"" << object.name << "\" (" << object.shape.path << "), material slot " << object.material << " */\n"
                  << "SS_FN SDF_FLOAT " << name << "(SDF_FLOAT px, SDF_FLOAT py, SDF_FLOAT pz) {\n" << w.body() << "    return " << d << ";\n}\n\n";
        if (has_analytic_normal(object.shape)) {
            FunctionWriter wn(&headers);
            std::string n = emit_normal(object.shape, "p", &wn);
            normals << "SS_FN float3 " << name << "_normal(float3 p) {\n" << wn.body() << "    return " << n << ";\n}\n\n";
            normal_cases << "    case " << index << ": *n = " << name << "_normal(p); return 1;\n";
        }
        slot_cases << "    case " << index << ": return " << object.material << ";\n";
        ++index;
    }
    NearestWriter nearest(scene, object_bounds, false, &headers), packet(scene, object_bounds, true, &headers);
    for (size_t i = 0; i < scene.emitters.size(); ++i) {
        const EmitterSphere& e = scene.emitters[i];
        headers.insert("sdf/primitives/sphere.h");
        std::string local = "p - " + vec3_literal(e.center);
        std::string distance = "fSphere_xyz(" + offset_components(e.center) + ", " + float_literal(e.radius) + ")";
        nearest.candidate(distance, int(index), "    ");
        packet.candidate(distance, int(index), "    ");
        slot_cases << "    case " << index << ": return " << e.material << ";\n";
        normal_cases << "    case " << index << ": *n = nSphere(" << local << ", " << float_literal(e.radius) << "); return 1;\n";
        ++index;
    }

    std::ostringstream out;
    out << "/* Generated by the dtoadq scene compiler from " << scene.file << "; do not edit.\n"
        << " * Objects: " << scene.objects.size() << ", emitters: " << scene.emitters.size()
        << " (" << nearest.box_tests() << " box tests). Lipschitz bound " << format_number(analysis.lipschitz)
        << (analysis.is_distance_bound ? "" : "; NOT a distance bound (a repetition breaks it)") << ". */\n"
        << "#ifndef SCENE_GENERATED_H\n#define SCENE_GENERATED_H\n\n"
        << "#define SCENE_LIPSCHITZ " << float_literal(analysis.lipschitz) << "\n"
        << "#define SCENE_EMITTER_COUNT " << scene.emitters.size() << "\n\n"
        << "#include \"single_source/vocabulary.h\"\n";
    for (const std::string& h : headers) out << "#include \"" << h << "\"\n";
    out << "\n" << functions.str();
    out << "#ifdef SDF_LANES\n"
        << "/* The field at SDF_LANES points at once (a packet kernel, kernels/march_packets.cl): the nearest\n"
        << " * distance only, exact in the lanes of `active`; a box test skips a group only when it may for\n"
        << " * every one of them. */\n"
        << "SS_FN SDF_FLOAT scene_distance_xyz(SDF_FLOAT px, SDF_FLOAT py, SDF_FLOAT pz, SDF_MASK active) {\n    SDF_FLOAT d = INFINITY;\n";
    out << (packet.box_tests() ? "    SDF_FLOAT b; /* a box test */\n" : "    (void)active;\n");
    out << packet.body() << "    return d;\n}\n\n#else /* one point at a time */\n\n" << normals.str();
    // A measurement build (-DSCENE_COUNT_EVALUATIONS, `dtoadq bench breakdown`) counts the distance
    // functions evaluated; the default build has no counter at all.
    out << "/* The nearest object or emitter (index: objects, then emitters) and its distance. */\n"
        << "#ifdef SCENE_COUNT_EVALUATIONS\n#define SCENE_COUNT_EVALUATION (*evaluations += 1u)\n"
        << "SS_FN float scene_nearest_counted_xyz(float px, float py, float pz, int* nearest, uint* evaluations) {\n"
        << "#else\n#define SCENE_COUNT_EVALUATION ((void)0)\n"
        << "SS_FN float scene_nearest_xyz(float px, float py, float pz, int* nearest) {\n#endif\n    int k = 0;\n    float d = INFINITY, e;\n";
    if (nearest.box_tests()) out << "    float b; /* a box test */\n";
    out << nearest.body() << "    *nearest = k;\n    return d;\n}\n\n"
        << "#ifdef SCENE_COUNT_EVALUATIONS\n"
        << "SS_FN float scene_nearest_xyz(float px, float py, float pz, int* nearest) {\n    uint n = 0u;\n"
        << "    return scene_nearest_counted_xyz(px, py, pz, nearest, &n);\n}\n\n"
        << "SS_FN float scene_distance_counted(float3 p, uint* evaluations) {\n    int k;\n"
        << "    return scene_nearest_counted_xyz(p.x, p.y, p.z, &k, evaluations);\n}\n#endif\n\n"
        << "SS_FN float scene_nearest(float3 p, int* nearest) { return scene_nearest_xyz(p.x, p.y, p.z, nearest); }\n\n"
        << "SS_FN int scene_material_slot(int nearest) {\n    switch (nearest) {\n"
        << slot_cases.str() << "    default: return 0;\n    }\n}\n\n"
        << "/* The field at a point given as three floats: what a vectorised march calls. */\n"
        << "SS_FN float scene_distance_xyz(float px, float py, float pz) {\n    int k;\n    return scene_nearest_xyz(px, py, pz, &k);\n}\n\n"
        << "SS_FN float scene_distance(float3 p) { return scene_distance_xyz(p.x, p.y, p.z); }\n\n"
        << "/* The distance and the material slot of the nearest object. */\n"
        << "SS_FN float scene_distance_material(float3 p, int* material) {\n    int k;\n"
        << "    float d = scene_nearest(p, &k);\n    *material = scene_material_slot(k);\n    return d;\n}\n\n"
        << "/* The nearest object's analytic normal where it is one primitive under rigid transforms and\n"
        << " * uniform scales; 0 (no normal) elsewhere. */\n"
        << "SS_FN int scene_analytic_normal(float3 p, float3* n) {\n    int k;\n    scene_nearest(p, &k);\n"
        << "    switch (k) {\n" << normal_cases.str() << "    default: return 0;\n    }\n}\n\n"
        << "#endif /* SDF_LANES */\n\n#endif\n";
    return out.str();
}

// scene/materials.h: apart from the geometry, so that a kernel that only marches (the packet
// kernels, the scene probe) is the same program for every material and is compiled once.
std::string generate_material_source(const Scene& scene, const std::vector<brdf::Material>& materials) {
    std::ostringstream out;
    out << "/* Generated by the dtoadq scene compiler from " << scene.file << "; do not edit. */\n"
        << "#ifndef SCENE_MATERIALS_H\n#define SCENE_MATERIALS_H\n\n"
        << "#define SCENE_MATERIAL_COUNT " << materials.size() << "\n\n"
        << "/* The BRDF features this scene's materials need (brdf/features.h). */\n"
        << brdf::feature_defines(materials) << "\n#endif\n";
    return out.str();
}

// The box of what is bounded: the camera, the lights, and each object's box about the origin
// (scene/lipschitz.hpp's extent) along its finite axes; then the sphere around that box. A scene
// with an endless part (a plane, an endless repetition) also holds the cube around the camera out to
// the distance of what it looks at: the environment's light subpaths start on a disk of this
// sphere's radius (kernels/bdpt_walk.h), so this is the part of an endless surface they cover;
// beyond it the camera's strategies carry the light alone (docs/bdpt.md).
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
    for (const EmitterSphere& e : scene.emitters) grow(glm::dvec3(e.center) - double(e.radius), glm::dvec3(e.center) + double(e.radius));
    for (const PointLight& p : scene.point_lights) grow(glm::dvec3(p.position), glm::dvec3(p.position));
    *center = Vec3(0.5 * (lo + hi));
    *radius = float(0.5 * glm::length(hi - lo));
}

// The box of every surface (CompiledScene::surface_lo, surface_hi): the union of the objects'
// boxes, each holding its solid with f >= dist(p, box) outside it, and of the emitters' spheres.
// A plane with an axis for its normal bounds its axis on one side, the side of its solid, which
// the objects' centred boxes cannot say: the ground y = 0 is the box y <= 0, so that a ray
// going up from a scene on the ground stops marching above its objects. All of space when a
// repetition breaks the bound: then f >= dist(p, box) need not hold.
void surface_box(const Scene& scene, const SceneAnalysis& analysis, Vec3* lo, Vec3* hi) {
    const float inf = std::numeric_limits<float>::infinity();
    *lo = Vec3(inf);
    *hi = Vec3(-inf);
    for (const Object& object : scene.objects) {
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
    for (const EmitterSphere& e : scene.emitters) {
        *lo = glm::min(*lo, e.center - Vec3(e.radius));
        *hi = glm::max(*hi, e.center + Vec3(e.radius));
    }
    if (!analysis.is_distance_bound) *lo = Vec3(-inf), *hi = Vec3(inf);
}

}  // namespace

std::string float_literal(float value) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.9g", double(value));
    std::string s = text;
    if (s.find_first_of(".ein") == std::string::npos) {
        s += ".0";
    } else if (s.find('.') == std::string::npos && s.find('e') != std::string::npos) {
        s.insert(s.find('e'), ".0");
    }
    return s + "f";
}

Scene apply_options(const Scene& scene, const CompileOptions& options) {
    Scene out = scene;
    std::vector<std::string> declared, objects;
    for (const MaterialSlot& slot : scene.materials)
        if (slot.source != "emitter") declared.push_back(slot.name);
    for (const Object& o : scene.objects) objects.push_back(o.name);
    for (const auto& [name, material] : options.material_overrides) {
        auto it = std::find_if(out.materials.begin(), out.materials.end(),
                               [&](const MaterialSlot& s) { return s.name == name && s.source != "emitter"; });
        if (it == out.materials.end())
            throw InputError(scene.file, "materials", "no material named \"" + name + "\" to replace (declared: " + list_names(declared) + ")");
        it->material = material;
        it->source = "override";
        // a reflecting emitter scatters with the declared material it names: it follows the override
        for (MaterialSlot& slot : out.materials)
            if (slot.emitter >= 0 && out.emitters[size_t(slot.emitter)].surface_material == name) slot.material = material;
    }
    for (const std::string& name : options.disabled_objects) {
        auto it = std::find_if(out.objects.begin(), out.objects.end(), [&](const Object& o) { return o.name == name; });
        if (it == out.objects.end())
            throw InputError(scene.file, "objects", "no object named \"" + name + "\" to disable (objects: " + list_names(objects) + ")");
        out.objects.erase(it);
    }
    if (out.objects.empty() && out.emitters.empty())
        throw InputError(scene.file, "objects", "nothing is left to render once the disabled objects are left out");
    return out;
}

CompiledScene compile_scene(const Scene& input, const CompileOptions& options) {
    Scene scene = apply_options(input, options);
    SceneAnalysis analysis = analyse_scene(scene);
    CompiledScene out;
    out.file = scene.file;
    for (const MaterialSlot& slot : scene.materials) {
        out.materials.push_back(slot.material);
        out.material_names.push_back(slot.name);
        out.emission.push_back(slot.emission);
    }
    out.emitters = scene.emitters;
    out.point_lights = scene.point_lights;
    scene_bounds(scene, &out.bounds_center, &out.bounds_radius);
    if (options.object_bounds) surface_box(scene, analysis, &out.surface_lo, &out.surface_hi);
    out.lipschitz = analysis.lipschitz;
    out.is_distance_bound = analysis.is_distance_bound;
    out.warnings = analysis.warnings;
    out.camera = scene.camera;
    out.environment = scene.environment;
    out.source = generate_source(scene, analysis, options.object_bounds);
    out.material_source = generate_material_source(scene, out.materials);
    return out;
}

}  // namespace lab::scene
