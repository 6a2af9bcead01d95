#include "scene/object_tree.hpp"

#include <algorithm>

namespace lab::scene {

namespace {

int build(std::vector<ObjectBox>& boxes, size_t begin, size_t end, std::vector<ObjectTreeNode>* nodes) {
    int index = int(nodes->size());
    nodes->emplace_back();
    ObjectTreeNode node;
    node.lo = boxes[begin].lo;
    node.hi = boxes[begin].hi;
    Vec3 centre_lo(0.5f * (boxes[begin].lo + boxes[begin].hi)), centre_hi = centre_lo;
    for (size_t i = begin; i < end; ++i) {
        node.lo = glm::min(node.lo, boxes[i].lo);
        node.hi = glm::max(node.hi, boxes[i].hi);
        Vec3 c = 0.5f * (boxes[i].lo + boxes[i].hi);
        centre_lo = glm::min(centre_lo, c);
        centre_hi = glm::max(centre_hi, c);
    }
    if (end - begin == 1) {
        node.object = boxes[begin].object;
    } else {
        Vec3 spread = centre_hi - centre_lo;
        int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : (spread.y >= spread.z ? 1 : 2);
        size_t middle = begin + (end - begin) / 2;
        // ties broken by the object's index, so the tree does not depend on the sort's whims
        std::nth_element(boxes.begin() + long(begin), boxes.begin() + long(middle), boxes.begin() + long(end),
                         [axis](const ObjectBox& a, const ObjectBox& b) {
                             float ca = a.lo[axis] + a.hi[axis], cb = b.lo[axis] + b.hi[axis];
                             return ca != cb ? ca < cb : a.object < b.object;
                         });
        node.left = build(boxes, begin, middle, nodes);
        node.right = build(boxes, middle, end, nodes);
    }
    (*nodes)[size_t(index)] = node;
    return index;
}

}  // namespace

std::vector<ObjectTreeNode> build_object_tree(std::vector<ObjectBox> boxes) {
    std::vector<ObjectTreeNode> nodes;
    if (!boxes.empty()) build(boxes, 0, boxes.size(), &nodes);
    return nodes;
}

}  // namespace lab::scene
