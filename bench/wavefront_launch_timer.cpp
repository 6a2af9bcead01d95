#include "bench/wavefront_launch_timer.hpp"

namespace lab::bench {

void WavefrontLaunchTimer::launch_ended(render::WavefrontLaunch kind, std::chrono::steady_clock::time_point start) {
    WavefrontLaunchTimes::Kind* times = nullptr;
    switch (kind) {
        case render::WavefrontLaunch::camera_step: times = &times_.camera_steps; break;
        case render::WavefrontLaunch::camera_march: times = &times_.camera_marches; break;
        case render::WavefrontLaunch::scatter_step: times = &times_.scatter_steps; break;
        case render::WavefrontLaunch::march: times = &times_.marches; break;
        case render::WavefrontLaunch::last_step: times = &times_.last_steps; break;
        case render::WavefrontLaunch::resolve: times = &times_.resolves; break;
    }
    times->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    times->launches += 1;
}

}  // namespace lab::bench
