#include "scene/shadow_catcher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdf/host/parameters.hpp"
#include "scene/lipschitz.hpp"
#include "scene/test_model.hpp"

namespace lab::scene {

Scene with_shadow_catcher(const Scene& scene) {
    Scene out = scene;
    float lowest = std::numeric_limits<float>::infinity();
    for (const Object& object : scene.objects) {
        const ShapeAnalysis a = analyse_shape(object.shape);
        if (!object.shadow_catcher && std::isfinite(a.box_half.y)) lowest = std::min(lowest, a.box_center.y - a.box_half.y);
    }
    if (!std::isfinite(lowest)) lowest = 0.0f;
    Node shape{Plane{Vec3(0.0f, 1.0f, 0.0f), -lowest}, "shadow_catcher", {}};
    // the ground's own plane, where the scene has one: the objects stand on it
    const auto ground = std::find_if(out.objects.begin(), out.objects.end(), [](const Object& o) { return o.name == kGroundObject; });
    if (ground != out.objects.end()) {
        shape = ground->shape;
        out.objects.erase(ground);
    }
    MaterialSlot slot;
    slot.name = kShadowCatcherObject;
    slot.source = "shadow catcher";
    slot.material = brdf::default_material();
    slot.material.weight_diffuse = 1.0f;
    slot.material.weight_glossy = slot.material.weight_specular = slot.material.weight_transmission = 0.0f;
    std::fill(std::begin(slot.material.albedo), std::end(slot.material.albedo), kShadowCatcherAlbedo);
    out.materials.push_back(slot);
    Object catcher;
    catcher.name = kShadowCatcherObject;
    catcher.material = int(out.materials.size() - 1);
    catcher.shape = std::move(shape);
    catcher.shadow_catcher = true;
    out.objects.push_back(std::move(catcher));
    return out;
}

}  // namespace lab::scene
