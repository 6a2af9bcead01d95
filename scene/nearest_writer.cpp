#include "scene/nearest_writer.hpp"

#include <cmath>
#include <limits>

#include "scene/object_functions.hpp"
#include "scene/source_literals.hpp"

namespace lab::scene {
namespace {

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

// fBox at p - center, in components.
std::string box_distance(Vec3 center, Vec3 half) {
    return "fBox_xyz(" + offset_components(center) + ", " + components_literal(half) + ")";
}

std::string box_distance(const ObjectTreeNode& n) {
    return box_distance(0.5f * (n.lo + n.hi), 0.5f * (n.hi - n.lo));
}

}  // namespace

NearestWriter::NearestWriter(const Scene& scene, bool object_bounds, bool packet, std::set<std::string>* headers, const std::vector<bool>& included)
    : headers_(headers), packet_(packet) {
    auto takes_part = [&](size_t i) { return included.empty() || included[i]; };
    std::vector<ObjectBox> boxes;
    std::vector<ShapeAnalysis> analyses;
    for (const Object& object : scene.objects) analyses.push_back(analyse_shape(object.shape));
    // An object whose box spans much of the scene (a wall, a floor slab) is near every point:
    // a group holding it would rarely be skipped, so it goes with the unbounded ones.
    Vec3 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
    auto finite = [](const ShapeAnalysis& a) {
        return std::isfinite(a.box_half.x) && std::isfinite(a.box_half.y) && std::isfinite(a.box_half.z) && a.broken.empty();
    };
    for (size_t i = 0; i < analyses.size(); ++i)
        if (const ShapeAnalysis& a = analyses[i]; takes_part(i) && finite(a)) lo = glm::min(lo, a.box_center - a.box_half), hi = glm::max(hi, a.box_center + a.box_half);
    float large = 0.5f * glm::length(hi - lo);
    std::vector<int> last;  // large objects with a box test of their own
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (!takes_part(i)) continue;
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

void NearestWriter::candidate(const std::string& expression, int index, const std::string& indent) {
    if (packet_) {
        body_ << indent << "d = fmin(d, " << expression << ");\n";
        return;
    }
    body_ << indent << "e = " << expression << ";\n"
          << indent << "SCENE_COUNT_EVALUATION;\n"
          << indent << "if (e < d || (e == d && " << index << " < k)) { d = e; k = " << index << "; }\n";
}

void NearestWriter::object(int i, const ShapeAnalysis* own_test, const std::string& indent) {
    std::string call = "scene_object_" + std::to_string(i) + "(px, py, pz)";
    if (!own_test) return candidate(call, i, indent);
    open_test(own_test->box_center, own_test->box_half, indent);
    candidate(call, i, indent + "    ");
    body_ << indent << "}\n";
}

// The tree in two passes, both straight-line code with literal boxes (a loop over a stack and a
// switch runs 8x slower on PoCL for 11x fewer evaluations). First a guess: down the nearer child
// (by box distance) at every node to one object, evaluated, so that the boxes of the second pass
// are tested against a small distance. Then every group in tree order, each guarded by its box
// test, skipping the guessed object (variable g).
void NearestWriter::traversal(const std::vector<ObjectTreeNode>& tree) {
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

void NearestWriter::guess(const std::vector<ObjectTreeNode>& tree, int k, const std::string& indent) {
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

void NearestWriter::node(const std::vector<ObjectTreeNode>& tree, int k, const std::string& indent) {
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
void NearestWriter::open_test(Vec3 center, Vec3 half, const std::string& indent) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(half[i])) half[i] = 3.0e38f;
    headers_->insert("sdf/primitives/box.h");
    body_ << indent << "b = " << box_distance(center, half) << ";\n"
          << indent << (packet_ ? "if (SDF_ANY(active && !(b > 0.0f && b > d))) {\n" : "if (!(b > 0.0f && b > d)) {\n");
    ++box_tests_;
}

}  // namespace lab::scene
