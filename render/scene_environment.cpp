#include "render/scene_environment.hpp"

namespace lab::render {

ibl::EnvironmentOptions scene_environment_options(const scene::Scene& scene, ibl::EnvironmentOptions options, std::string* source) {
    const scene::EnvironmentSpec& spec = *scene.environment;
    options.rotation_degrees += spec.rotation_degrees;
    options.exposure_stops += spec.exposure;
    options.origin = scene.file + ": environment";
    *source = spec.file.empty() ? "constant:" + std::to_string(spec.constant.x) + "," + std::to_string(spec.constant.y) + "," +
                                      std::to_string(spec.constant.z)
                                : spec.file;
    return options;
}

std::optional<ibl::Environment> load_scene_environment(const scene::Scene& scene, ibl::EnvironmentOptions options, std::string* name) {
    if (!scene.environment) return std::nullopt;
    const scene::EnvironmentSpec& spec = *scene.environment;
    std::string source;
    options = scene_environment_options(scene, options, &source);
    if (name) *name = source;
    if (!spec.file.empty()) return ibl::load_environment(spec.file, options);
    return ibl::Environment::constant(spec.constant, source, options);
}

}  // namespace lab::render
