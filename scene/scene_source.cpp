#include "scene/scene_source.hpp"

namespace lab::scene {

opencl::AssembledSource assemble_scene_kernel(const std::string& entry, const CompiledScene& scene) {
    const std::string& generated = scene.source;
    return opencl::assemble_source(entry, [&generated](const std::string& path) -> std::string_view {
        if (path == kGeneratedScenePath) return generated;
        return opencl::embedded_kernel_file(path);
    });
}

}  // namespace lab::scene
