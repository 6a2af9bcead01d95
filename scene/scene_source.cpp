#include "scene/scene_source.hpp"

namespace lab::scene {

opencl::AssembledSource assemble_scene_kernel(const std::string& entry, const CompiledScene& scene) {
    return opencl::assemble_source(entry, [&scene](const std::string& path) -> std::string_view {
        if (path == kGeneratedScenePath) return scene.source;
        if (path == kSceneMaterialsPath) return scene.material_source;
        return opencl::embedded_kernel_file(path);
    });
}

}  // namespace lab::scene
