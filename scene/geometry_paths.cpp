#include "scene/geometry_paths.hpp"

#include "scene/object_functions.hpp"

namespace lab::scene {
namespace {

// The first node, from the root down, that keeps an object from a closed-form hit.
const Node* first_field_node(const Node& node) {
    if (std::holds_alternative<Translate>(node.kind) || std::holds_alternative<Rotate>(node.kind) ||
        std::holds_alternative<Scale>(node.kind))
        return first_field_node(node.children[0]);
    return node.children.empty() ? nullptr : &node;
}

const char* field_reason(const Node& node) {
    if (std::holds_alternative<Combine>(node.kind)) return "a combination of shapes";
    if (std::holds_alternative<Repeat>(node.kind) || std::holds_alternative<RepeatLimited>(node.kind)) return "a domain repetition";
    if (std::holds_alternative<Displace>(node.kind)) return "a displacement";
    return "not a plain primitive";
}

}  // namespace

bool object_is_exact(const Scene& scene, const Object& object) { return !scene.march_everything && has_analytic_normal(object.shape); }

bool emitter_is_exact(const Scene& scene, const Emitter& emitter) { return !scene.march_everything || emitter.shape != EmitterShape::sphere; }

int marched_count(const Scene& scene) {
    int n = 0;
    for (const Emitter& e : scene.emitters) n += emitter_is_exact(scene, e) ? 0 : 1;
    for (const Object& o : scene.objects) n += object_is_exact(scene, o) ? 0 : 1;
    return n;
}

std::vector<std::string> geometry_paths(const Scene& scene) {
    std::vector<std::string> lines;
    for (const Object& o : scene.objects) {
        std::string line = "object \"" + o.name + "\" (" + o.shape.path + "): ";
        if (object_is_exact(scene, o))
            line += "exact intersection";
        else if (scene.march_everything)
            line += "sphere-traced (--geometry march)";
        else
            line += std::string("sphere-traced: ") + first_field_node(o.shape)->path + " is " + field_reason(*first_field_node(o.shape));
        lines.push_back(line);
    }
    static const char* const kShapes[] = {"sphere", "rect", "disk"};
    for (size_t k = 0; k < scene.emitters.size(); ++k) {
        const Emitter& e = scene.emitters[k];
        std::string line = std::string("emissive ") + kShapes[int(e.shape)] + " " + std::to_string(k) + ": ";
        if (!emitter_is_exact(scene, e)) line += "sphere-traced (--geometry march)";
        else line += e.shape == EmitterShape::sphere || !scene.march_everything ? "exact intersection" : "exact intersection (it has no volume to march)";
        lines.push_back(line);
    }
    return lines;
}

}  // namespace lab::scene
