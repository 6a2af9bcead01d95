#include "kernels/host/material_layout.hpp"

#include <cstddef>
#include <string>

#include "brdf/brdf.hpp"

namespace lab::kernels {

// Plain floats and ints only (brdf/material.h): 49 floats and 4 ints, no padding on either side.
static_assert(sizeof(brdf::Material) == 53 * 4, "brdf::Material changed: update kernels/material_layout.h");

void check_material_layout(const opencl::Runtime& runtime, const opencl::Program& program) {
    opencl::KernelHandle layout = program.kernel("brdf_material_layout");
    int device[5] = {0, 0, 0, 0, 0};
    opencl::BufferHandle out = runtime.buffer(sizeof(device), CL_MEM_WRITE_ONLY);
    opencl::set_kernel_arg(layout, 0, out);
    runtime.launch_1d(layout, 1, 1);
    runtime.read(out, device, sizeof(device));
    const int host[5] = {int(sizeof(brdf::Material)), int(offsetof(brdf::Material, roughness)), int(offsetof(brdf::Material, ior)),
                         int(offsetof(brdf::Material, model)), int(offsetof(brdf::Material, distribution))};
    auto text = [](const int* v) {
        return std::to_string(v[0]) + "/" + std::to_string(v[1]) + "/" + std::to_string(v[2]) + "/" + std::to_string(v[3]) + "/" +
               std::to_string(v[4]);
    };
    for (int k = 0; k < 5; ++k)
        if (device[k] != host[k])
            throw opencl::OpenClError("Material layout differs between host and " + runtime.device().device_name + " (size/offsets host " +
                                      text(host) + ", device " + text(device) + ")");
}

}  // namespace lab::kernels
