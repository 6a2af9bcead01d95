// The lab's kernel sources as the binary carries them: every kernels/*.cl and every single-source
// header (kernels/, brdf/, sdf/, ibl/, film/, single_source/) is embedded at build time, so a kernel builds
// without the source tree.
#pragma once

#include <string>
#include <string_view>

#include "opencl/runtime.hpp"

namespace lab::kernels {

// An embedded file's text by repository-relative path ("brdf/ggx.h"); empty when there is none.
std::string_view embedded_kernel_file(const std::string& path);

// `entry` assembled over the embedded files (opencl::assemble_source).
opencl::AssembledSource assemble_embedded_source(const std::string& entry);

// `entry` assembled over the embedded files and built. Throws opencl::KernelBuildError or
// opencl::OpenClError.
opencl::Program build_embedded(const opencl::Runtime& runtime, const std::string& entry, const std::string& options);

}  // namespace lab::kernels
