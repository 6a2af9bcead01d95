#include "render/opencl_launch.hpp"

namespace lab::render {

void launch_range(const opencl::Runtime& runtime, const opencl::KernelHandle& kernel, PixelRange range, size_t local, size_t total) {
    const bool ends_image = size_t(range.first) + size_t(range.count) >= total;
    while (local > 1 && !ends_image && size_t(range.count) % local != 0) local /= 2;
    cl_uint arguments = 0;
    opencl::check_cl(clGetKernelInfo(kernel.get(), CL_KERNEL_NUM_ARGS, sizeof(arguments), &arguments, nullptr), "clGetKernelInfo");
    opencl::set_kernel_arg(kernel, arguments - 1, cl_int(range.first));
    runtime.launch_1d(kernel, size_t(range.count), local);
}

}  // namespace lab::render
