#include "kernels/host/scene_kernel_source.hpp"

#include "kernels/host/embedded_sources.hpp"

namespace lab::kernels {

opencl::AssembledSource assemble_scene_kernel(const std::string& entry, const scene::CompiledScene& scene) {
    return opencl::assemble_source(entry, [&scene](const std::string& path) -> std::string_view {
        if (path == kGeneratedScenePath) return scene.source;
        if (path == kSceneMaterialsPath) return scene.material_source;
        return embedded_kernel_file(path);
    });
}

}  // namespace lab::kernels
