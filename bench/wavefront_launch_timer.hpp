// Where the wavefront's time goes, launch by launch (`dtoadq bench breakdown`): each kind's seconds,
// with the host waiting for every launch to end, and its number of launches.
#pragma once

#include "render/wavefront_driver.hpp"

namespace lab::bench {

struct WavefrontLaunchTimes {
    struct Kind {
        double seconds = 0.0;
        int launches = 0;
    };
    Kind camera_steps;    // render::WavefrontLaunch::camera_step
    Kind camera_marches;  // camera_march
    Kind scatter_steps;   // scatter_step
    Kind marches;         // march
    Kind last_steps;      // last_step
    Kind resolves;        // resolve
    double total() const {
        return camera_steps.seconds + camera_marches.seconds + scatter_steps.seconds + marches.seconds + last_steps.seconds + resolves.seconds;
    }
};

// Observes a renderer's wavefront (render::OpenClRenderer::observe_wavefront_launches) and adds up
// its launches' times by kind.
class WavefrontLaunchTimer final : public render::WavefrontLaunchObserver {
public:
    void launch_ended(render::WavefrontLaunch kind, std::chrono::steady_clock::time_point start) override;
    const WavefrontLaunchTimes& times() const { return times_; }
    // Starts again at 0.
    void restart() { times_ = WavefrontLaunchTimes{}; }

private:
    WavefrontLaunchTimes times_;
};

}  // namespace lab::bench
