#include "render/opencl_launch.hpp"

namespace lab::render {

void launch_range(const opencl::Runtime& runtime, const opencl::KernelHandle& kernel, PixelRange range, size_t local, size_t total) {
    const bool ends_image = size_t(range.first) + size_t(range.count) >= total;
    while (local > 1 && (size_t(range.first) % local != 0 || (!ends_image && size_t(range.count) % local != 0))) local /= 2;
    runtime.launch_1d(kernel, size_t(range.count), local, size_t(range.first));
}

}  // namespace lab::render
