// A bounding-volume tree over a scene's bounded objects, for the generated distance field: a march
// step tests a group's box before evaluating anything in it, so the cost of a point grows with the
// objects near it and the tree's depth, not with every object of the scene (a kernel holds only
// what its scene uses, and a point evaluates only what is near it). The boxes come from scene/lipschitz.hpp, where
// f(p) >= dist(p, box) outside an object's box: a group whose box is farther than the nearest
// surface found so far cannot change the minimum.
#pragma once

#include <vector>

#include "scene/scene.hpp"

namespace lab::scene {

// One object's box (finite on every axis) and whether it is worth its own box test.
struct ObjectBox {
    int object = 0;  // its index among the scene's objects
    Vec3 lo{0.0f}, hi{0.0f};
    bool own_test = false;
};

// A node: a leaf holds one object; an inner node two children and the box around both.
struct ObjectTreeNode {
    Vec3 lo{0.0f}, hi{0.0f};
    int object = -1;  // >= 0: a leaf
    int left = -1, right = -1;
};

// Top-down, split at the median of the boxes' centres along the widest axis of those centres;
// nodes[0] is the root (an empty vector for no boxes).
std::vector<ObjectTreeNode> build_object_tree(std::vector<ObjectBox> boxes);

}  // namespace lab::scene
