// A launch of a render kernel over a range of pixels (or paths), shared by the OpenCL renderer's
// work-item kernel and the wavefront's kernels.
#pragma once

#include <cstddef>

#include "opencl/runtime.hpp"
#include "render/renderer.hpp"

namespace lab::render {

// Work-items range.first .. range.first + range.count - 1 of `kernel`, of `total` for the image. The
// range starts at a multiple of its granularity and spans whole granules unless it ends the image,
// where the kernels stop by themselves. A work-group size set above the granularity (bench
// breakdown's study) would round a partial range up into work-items of the next launch: such a
// launch takes the largest halving of it that fits the range.
void launch_range(const opencl::Runtime& runtime, const opencl::KernelHandle& kernel, PixelRange range, size_t local, size_t total);

}  // namespace lab::render
