// A launch of a render kernel over a range of pixels (or paths), shared by the OpenCL renderer's
// work-item kernels and the wavefront's kernels.
#pragma once

#include <cstddef>

#include "opencl/runtime.hpp"
#include "render/renderer.hpp"

namespace lab::render {

// Work-items range.first .. range.first + range.count - 1 of `kernel`, of `total` for the image. The
// first one is the kernel's last argument (an int), set here, and the launch is at offset 0: PoCL
// compiles a kernel once more for a launch at a global offset (its work-group functions are
// specialised for offset 0), so a render over part of the image would build every kernel twice.
// The range spans whole granules of its granularity unless it ends the image, where the kernels
// stop by themselves. A work-group size set above the granularity (bench breakdown's study) would
// round a partial range up into work-items of the next launch: such a launch takes the largest
// halving of it that fits the range.
void launch_range(const opencl::Runtime& runtime, const opencl::KernelHandle& kernel, PixelRange range, size_t local, size_t total);

}  // namespace lab::render
