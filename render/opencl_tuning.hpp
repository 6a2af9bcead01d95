// How the OpenCL renderer builds and launches its kernels (render/opencl_renderer,
// render/wavefront_driver): choices of speed and measurement that leave every image's bits as they are.
#pragma once

#include <string>

namespace lab::render {

struct OpenClTuning {
    int local_size = 0;               // work-group size; 0: the renderer's default (64, or the kernel's maximum)
    std::string extra_build_options;  // appended to the build options (e.g. a -D forcing a cold build)
    // The entry file, among the embedded kernel sources, of a program to build in place of the
    // integrator's own (IntegratorDescriptor::program); it must define the same kernels. Empty: the
    // integrator's own. For measurement builds that change what the kernels compute.
    std::string program;
    // The path tracer on a CPU device: the wavefront, whose packet kernels march eight rays at a
    // time on the vector lanes (kernels/path_tracer_wavefront.h); false, or a GPU: every ray marched
    // in its path's work-item (the same bits).
    bool packets = true;
    // Paths the wavefront keeps in flight: as many samples of every pixel as make up about this many
    // (at least one); 0: the wavefront's default (render/wavefront_driver.cpp). The same bits whatever it is.
    int wavefront_paths = 0;
};

}  // namespace lab::render
