#include "render/display_filter.hpp"

#include <optional>

#include "kernels/host/denoise_device.hpp"
#include "opencl/runtime.hpp"

namespace lab::render {

namespace {

class HostDisplayFilter final : public DisplayFilter {
public:
    bool passes(film::AtrousBuffers* buffers, const film::DenoiseOptions& options, const film::FilterCancelled& cancelled) override {
        return film::atrous_passes(buffers, options, cancelled);
    }
};

class DeviceDisplayFilter final : public DisplayFilter {
public:
    explicit DeviceDisplayFilter(std::string selector) : selector_(std::move(selector)) {}
    void prepare() override {
        if (!runtime_) runtime_.emplace(selector_);
        if (!denoiser_) denoiser_.emplace(*runtime_);
    }
    bool passes(film::AtrousBuffers* buffers, const film::DenoiseOptions& options, const film::FilterCancelled& cancelled) override {
        prepare();
        return denoiser_->passes(buffers, options, cancelled);
    }

private:
    std::string selector_;
    std::optional<opencl::Runtime> runtime_;  // declared before the denoiser, which refers to it
    std::optional<kernels::DeviceDenoiser> denoiser_;
};

}  // namespace

std::unique_ptr<DisplayFilter> host_display_filter() { return std::make_unique<HostDisplayFilter>(); }

std::unique_ptr<DisplayFilter> device_display_filter(const std::string& selector) { return std::make_unique<DeviceDisplayFilter>(selector); }

}  // namespace lab::render
