// Lipschitz analysis of a scene's distance field: a bound L on |grad f| for every node, so sphere
// tracing can step by |f| / L (Hart 1996), and the conditions under which domain repetition keeps
// the field a distance bound at all (docs/scenes.md, "Lipschitz bound").
#pragma once

#include <array>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace lab::scene {

struct ShapeAnalysis {
    float lipschitz = 1.0f;
    // Half extents of a box B about the node's local origin such that f(p) >= dist(p, B) outside B,
    // so the solid lies in B; a component is infinite where the solid is unbounded along that axis
    // (a plane, an infinite repetition).
    Vec3 extent{0.0f};
    // mirror_symmetric[i]: f is unchanged by p_i -> -p_i (conservative: false when unsure).
    std::array<bool, 3> mirror_symmetric{false, false, false};
    // Why the field is not a distance bound: "PATH: reason", one per offending repetition.
    std::vector<std::string> broken;
    // A tighter box of the same kind, not about the origin: centre box_center, half extents
    // box_half (infinite along unbounded axes, where the centre is 0), with f(p) >= dist(p, box)
    // outside it. The scene compiler skips an object whose box is no nearer than the nearest
    // surface found so far, which leaves the minimum, and so the field, as it was.
    Vec3 box_center{0.0f};
    Vec3 box_half{0.0f};
};

ShapeAnalysis analyse_shape(const Node& node);

struct SceneAnalysis {
    float lipschitz = 1.0f;              // max over the objects and emitters
    bool is_distance_bound = true;       // false when a repetition breaks the bound
    std::vector<std::string> warnings;   // "FILE: ..." lines for the command line to print
};

SceneAnalysis analyse_scene(const Scene& scene);

}  // namespace lab::scene
