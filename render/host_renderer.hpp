// The same integrators compiled as C++ and run on the host's threads, one pixel at a time, with the
// same random numbers as the OpenCL build (kernels/path_tracer.h and the headers it includes are
// single source). The scene's distance field is the host interpreter's (scene/interpreter.hpp),
// which evaluates the same sdf/ headers the compiled source calls. For stepping through a path in
// a debugger, running it under AddressSanitizer and UBSan, and checking the device against it.
#pragma once

#include "render/renderer.hpp"

namespace lab::render {

// Bytes of a path's state between the OpenCL wavefront's steps (kernels/path_tracer.h, PathState):
// four-byte members only, so the host's layout, where the struct is compiled, is the kernels'.
size_t path_state_bytes();

class HostRenderer final : public Renderer {
public:
    // threads: 0 uses every hardware thread.
    explicit HostRenderer(RenderInput input, int threads = 0);

    std::string device_description() const override;

private:
    void build_kernel() override {}  // nothing to build: the integrator is compiled into the binary
    void upload_scene() override {}  // the scene is read where it is
    void clear_film() override;
    void launch(const kernel::RenderKernelSettings& launch_settings, PixelRange pixels) override;
    FilmReadback read_film() const override;
    void write_film(const FilmReadback& film) override;
    void read_ray_counts(uint64_t* rays, uint64_t* lost) const override;

    int threads_ = 1;
    FilmReadback film_;
    std::vector<uint32_t> rays_, lost_;
};

}  // namespace lab::render
