#include "bench/wavefront_launch_timer.hpp"

namespace lab::bench {

void WavefrontLaunchTimer::launch_ended(render::WavefrontLaunch kind, std::chrono::steady_clock::time_point start) {
    WavefrontLaunchTimes::Kind* k = nullptr;
    switch (kind) {
        case render::WavefrontLaunch::camera_step: k = &times_.camera_steps; break;
        case render::WavefrontLaunch::camera_march: k = &times_.camera_marches; break;
        case render::WavefrontLaunch::scatter_step: k = &times_.scatter_steps; break;
        case render::WavefrontLaunch::march: k = &times_.marches; break;
        case render::WavefrontLaunch::last_step: k = &times_.last_steps; break;
        case render::WavefrontLaunch::resolve: k = &times_.resolves; break;
    }
    k->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    k->launches += 1;
}

}  // namespace lab::bench
