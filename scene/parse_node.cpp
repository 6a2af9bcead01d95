#include "scene/parse_node.hpp"

#include <cmath>
#include <functional>
#include <map>

#include "common/input_error.hpp"

namespace lab::scene {
namespace {

// Cell indices stay exact in a float far beyond this.
constexpr int kRepeatCountMax = 1000000;

Node child_of(const Fields& f) { return parse_node(f.at("child"), f.path_of("child"), f.file()); }

std::vector<Node> children_of(const Fields& f) {
    const Json& list = f.at("children");
    if (!list.is_array()) f.fail("children", std::string("expected an array of nodes, got ") + list.type_name());
    if (list.size() < 2) f.fail("children", "a combinator needs at least 2 children, got " + std::to_string(list.size()));
    std::vector<Node> out;
    for (size_t i = 0; i < list.size(); ++i) out.push_back(parse_node(list[i], element_path(f.path_of("children"), i), f.file()));
    return out;
}

// Rodrigues' formula, in double, for a unit axis: R = cos I + sin [a]x + (1 - cos) a a^T.
glm::dmat3 axis_angle(glm::dvec3 axis, double degrees) {
    double radians = degrees * (3.14159265358979323846 / 180.0);
    double c = std::cos(radians), s = std::sin(radians);
    glm::dmat3 cross_matrix(0.0, axis.z, -axis.y,   // column 0
                            -axis.z, 0.0, axis.x,   // column 1
                            axis.y, -axis.x, 0.0);  // column 2
    return c * glm::dmat3(1.0) + s * cross_matrix + (1.0 - c) * glm::outerProduct(axis, axis);
}

// cos(90 degrees) is 6e-17 in double, not 0: entries that small are rounding, and exact zeros keep
// a quarter turn's field exactly mirror-symmetric (scene/lipschitz.hpp) and its code short.
glm::mat3 snapped(const glm::dmat3& r) {
    glm::mat3 out(r);
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k)
            if (std::fabs(r[c][k]) < 1e-12) out[c][k] = 0.0f;
    return out;
}

glm::mat3 parse_rotation(const Fields& f) {
    bool by_axis = f.has("axis") || f.has("degrees");
    if (by_axis && f.has("euler_degrees"))
        f.fail("euler_degrees", "give either \"axis\" and \"degrees\" or \"euler_degrees\", not both");
    if (!by_axis && !f.has("euler_degrees"))
        throw InputError(f.file(), f.path(), "a rotation needs \"axis\" and \"degrees\", or \"euler_degrees\"");
    if (by_axis) {
        glm::dvec3 axis = glm::normalize(glm::dvec3(f.nonzero_vec3("axis")));
        return snapped(axis_angle(axis, f.number("degrees")));
    }
    // Fixed axes x, then y, then z: R = Rz Ry Rx.
    Vec3 e = f.vec3("euler_degrees");
    return snapped(axis_angle({0, 0, 1}, e.z) * axis_angle({0, 1, 0}, e.y) * axis_angle({1, 0, 0}, e.x));
}

// Per axis >= 0; 0 leaves that axis unrepeated (sdf/domain/mod3.h), but some axis must repeat.
Vec3 repeat_period(const Fields& f) {
    Vec3 period = f.non_negative_vec3("period");
    if (period.x == 0.0f && period.y == 0.0f && period.z == 0.0f) f.fail("period", "must not be the zero vector");
    return period;
}

Combine parse_combine(const Fields& f, Combinator op, bool blended) {
    return Combine{op, blended ? f.positive("radius") : 0.0f};
}

struct NodeType {
    std::vector<std::string> keys;  // besides "type"
    std::function<Node(const Fields&)> parse;
};

Node leaf(NodeKind kind, const Fields& f) { return Node{kind, f.path(), {}}; }
Node unary(NodeKind kind, const Fields& f) { return Node{kind, f.path(), {child_of(f)}}; }

NodeType combinator(Combinator op, bool blended) {
    std::vector<std::string> keys = {"children"};
    if (blended) keys.push_back("radius");
    return {keys, [op, blended](const Fields& f) { return Node{parse_combine(f, op, blended), f.path(), children_of(f)}; }};
}

const std::vector<std::pair<std::string, NodeType>>& node_types() {
    static const std::vector<std::pair<std::string, NodeType>> types = {
        {"sphere", {{"radius"}, [](const Fields& f) { return leaf(Sphere{f.positive("radius")}, f); }}},
        {"plane", {{"normal", "offset"}, [](const Fields& f) {
             Vec3 n = Vec3(glm::normalize(glm::dvec3(f.nonzero_vec3("normal"))));
             return leaf(Plane{n, f.has("offset") ? f.number("offset") : 0.0f}, f);
         }}},
        {"box", {{"half_size"}, [](const Fields& f) { return leaf(Box{f.positive_vec3("half_size")}, f); }}},
        {"round_box", {{"half_size", "radius"}, [](const Fields& f) {
             Vec3 h = f.positive_vec3("half_size");
             float r = f.positive("radius");
             float smallest = std::fmin(h.x, std::fmin(h.y, h.z));
             if (r > smallest)
                 f.fail("radius", "value " + format_number(r) + " must be <= the smallest half_size " + format_number(smallest));
             return leaf(RoundBox{h, r}, f);
         }}},
        {"torus", {{"major_radius", "minor_radius"}, [](const Fields& f) {
             return leaf(Torus{f.positive("major_radius"), f.positive("minor_radius")}, f);
         }}},
        {"cylinder", {{"radius", "half_height"}, [](const Fields& f) {
             return leaf(Cylinder{f.positive("radius"), f.positive("half_height")}, f);
         }}},
        {"capsule", {{"radius", "half_height"}, [](const Fields& f) {
             return leaf(Capsule{f.positive("radius"), f.positive("half_height")}, f);
         }}},
        {"cone", {{"radius", "height"}, [](const Fields& f) { return leaf(Cone{f.positive("radius"), f.positive("height")}, f); }}},
        {"translate", {{"offset", "child"}, [](const Fields& f) { return unary(Translate{f.vec3("offset")}, f); }}},
        {"rotate", {{"axis", "degrees", "euler_degrees", "child"}, [](const Fields& f) { return unary(Rotate{parse_rotation(f)}, f); }}},
        {"scale", {{"factor", "child"}, [](const Fields& f) { return unary(Scale{f.positive("factor")}, f); }}},
        {"union", combinator(Combinator::union_, false)},
        {"intersection", combinator(Combinator::intersection, false)},
        {"subtraction", combinator(Combinator::subtraction, false)},
        {"smooth_union", combinator(Combinator::smooth_union, true)},
        {"round_union", combinator(Combinator::round_union, true)},
        {"round_intersection", combinator(Combinator::round_intersection, true)},
        {"round_subtraction", combinator(Combinator::round_subtraction, true)},
        {"chamfer_union", combinator(Combinator::chamfer_union, true)},
        {"chamfer_intersection", combinator(Combinator::chamfer_intersection, true)},
        {"chamfer_subtraction", combinator(Combinator::chamfer_subtraction, true)},
        {"repeat", {{"period", "child"}, [](const Fields& f) { return unary(Repeat{repeat_period(f)}, f); }}},
        {"repeat_limited", {{"period", "count_min", "count_max", "child"}, [](const Fields& f) {
             RepeatLimited r{repeat_period(f), f.integer_vec3("count_min", kRepeatCountMax),
                             f.integer_vec3("count_max", kRepeatCountMax)};
             for (int c = 0; c < 3; ++c) {
                 std::string at_max = element_path(f.path_of("count_max"), size_t(c));
                 if (r.count_min[c] > r.count_max[c])
                     throw InputError(f.file(), at_max,
                                      "value " + format_number(r.count_max[c]) + " must be >= count_min " + format_number(r.count_min[c]));
                 if (r.period[c] == 0.0f && (r.count_min[c] != 0.0f || r.count_max[c] != 0.0f))
                     throw InputError(f.file(), at_max, "counts must be 0 along an axis whose period is 0 (not repeated)");
             }
             return unary(r, f);
         }}},
        {"displace", {{"amplitude", "frequency", "child"}, [](const Fields& f) {
             return unary(Displace{f.positive("amplitude"), f.positive("frequency")}, f);
         }}},
    };
    return types;
}

}  // namespace

const std::vector<std::string>& node_type_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const auto& [name, type] : node_types()) out.push_back(name);
        return out;
    }();
    return names;
}

Node parse_node(const Json& value, const std::string& path, const std::string& file) {
    if (!value.is_object()) throw InputError(file, path, std::string("expected a node object, got ") + value.type_name());
    if (!value.contains("type")) throw InputError(file, field_path(path, "type"), "missing required key");
    const Json& type = value.at("type");
    if (!type.is_string()) throw InputError(file, field_path(path, "type"), std::string("expected a string, got ") + type.type_name());
    std::string name = type.get<std::string>();
    for (const auto& [type_name, node_type] : node_types()) {
        if (type_name != name) continue;
        std::vector<std::string> allowed = {"type"};
        allowed.insert(allowed.end(), node_type.keys.begin(), node_type.keys.end());
        return node_type.parse(Fields(value, path, file, allowed));
    }
    std::string list;
    for (const std::string& n : node_type_names()) list += (list.empty() ? "" : ", ") + n;
    throw InputError(file, field_path(path, "type"), "unknown node type \"" + name + "\" (expected one of: " + list + ")");
}

}  // namespace lab::scene
