// The nearest-object writer of the scene compiler: the body of scene_nearest (one point) and of
// the packet kernels' scene_distance_xyz, with the object tree's box tests.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "scene/lipschitz.hpp"
#include "scene/object_tree.hpp"
#include "scene/scene.hpp"

namespace lab::scene {

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
    // Only the objects for which `included` is true (all when it is empty) take part: the march's
    // field leaves out the objects intersected exactly.
    NearestWriter(const Scene& scene, bool object_bounds, bool packet, std::set<std::string>* headers, const std::vector<bool>& included = {});

    // A surface at distance `expression`, index `index`.
    void candidate(const std::string& expression, int index, const std::string& indent);
    const std::string body() const { return body_.str(); }
    int box_tests() const { return box_tests_; }

private:
    void object(int i, const ShapeAnalysis* own_test, const std::string& indent);
    void traversal(const std::vector<ObjectTreeNode>& tree);
    void guess(const std::vector<ObjectTreeNode>& tree, int k, const std::string& indent);
    void node(const std::vector<ObjectTreeNode>& tree, int k, const std::string& indent);
    void open_test(Vec3 center, Vec3 half, const std::string& indent);

    std::set<std::string>* headers_;
    std::ostringstream body_;
    std::map<int, std::optional<ShapeAnalysis>> own_test_;
    int box_tests_ = 0;
    bool guessed_ = false;
    bool packet_;
};

}  // namespace lab::scene
