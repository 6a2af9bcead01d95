// The display denoiser's passes (film/denoise.hpp) apart from the renderer, for a thread of its own
// that filters the image shown while the renderer goes on rendering (the viewer's): it shares no
// queue, buffer or kernel with the renderer, so neither waits for the other's work.
#pragma once

#include <memory>
#include <string>

#include "film/denoise.hpp"

namespace lab::render {

class DisplayFilter {
public:
    virtual ~DisplayFilter() = default;
    // Builds what the passes need (a program), so that the first filter does not: on the thread
    // that will filter, before it is needed. Throws what passes would.
    virtual void prepare() {}
    // As film::atrous_passes; false: `cancelled` said so between two passes.
    virtual bool passes(film::AtrousBuffers* buffers, const film::DenoiseOptions& options, const film::FilterCancelled& cancelled) = 0;
};

// On the calling thread, on the host.
std::unique_ptr<DisplayFilter> host_display_filter();
// On the OpenCL device `selector` names (opencl::select_device), in a context and queue of its own,
// made with kernels/denoise.cl's program at the first call, on the thread that calls.
std::unique_ptr<DisplayFilter> device_display_filter(const std::string& selector);

}  // namespace lab::render
