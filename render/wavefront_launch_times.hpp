// Where the wavefront's time goes, launch by launch (`dtoadq bench breakdown`): each kind's seconds,
// with the host waiting for every launch to end, and its number of launches.
#pragma once

namespace lab::render {

struct WavefrontLaunchTimes {
    struct Kind {
        double seconds = 0.0;
        int launches = 0;
    };
    Kind camera_steps;    // a thin lens's camera rays, one path per work-item, left in the buffers
    Kind camera_marches;  // the camera rays' packets (a pinhole's rays begun in them)
    Kind scatter_steps;   // a step that leaves rays to march (the paths begun, surfaces scattered, light samples drawn)
    Kind marches;         // the packets of the rays and shadow rays those steps leave
    Kind last_steps;      // the step that leaves nothing to march (the last shadow rays resolved, escapes looked up)
    Kind resolves;        // several samples in flight: their paths added to the film
    double total() const {
        return camera_steps.seconds + camera_marches.seconds + scatter_steps.seconds + marches.seconds + last_steps.seconds + resolves.seconds;
    }
};

}  // namespace lab::render
