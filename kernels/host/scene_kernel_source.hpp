// Kernel sources that include a compiled scene: the virtual files "scene/generated.h" and
// "scene/materials.h" are served from the CompiledScene, every other file from the ones embedded in
// the binary. Used by the scene probe (kernels/scene_probe.cl, the agreement test) and the render
// kernels.
#pragma once

#include <string>

#include "opencl/kernel_source.hpp"
#include "scene/compile.hpp"

namespace lab::kernels {

// The path kernels include the compiled scene's geometry by,
inline constexpr const char* kGeneratedScenePath = "scene/generated.h";
// and its materials' feature switches by (CompiledScene::material_source).
inline constexpr const char* kSceneMaterialsPath = "scene/materials.h";

// OpenCL build options for scene kernels: correctly rounded division and square root, as on the
// host, so the compiled field agrees with the host interpreter.
inline constexpr const char* kSceneBuildOptions = "-cl-std=CL1.2 -cl-fp32-correctly-rounded-divide-sqrt";

// Assembles `entry` (e.g. "kernels/scene_probe.cl") with the scene's sources behind
// "scene/generated.h" and "scene/materials.h". Throws lab::opencl::OpenClError for an include that
// resolves to nothing.
opencl::AssembledSource assemble_scene_kernel(const std::string& entry, const scene::CompiledScene& scene);

}  // namespace lab::kernels
