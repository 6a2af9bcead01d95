// The figures `dtoadq view --stats` prints: interface frame times (median, 95th percentile) and
// the time from a scripted change to the first frame that shows it, and to the first that shows it
// denoised.
#pragma once

#include <string>
#include <vector>

namespace lab::viewer {

struct FrameStats {
    std::vector<double> frame_seconds;   // every interface frame, start to start
    std::vector<double> change_seconds;  // per scripted change: submit to the first frame showing it
    std::vector<double> denoised_seconds;  // per scripted change with the denoiser on: submit to the first frame showing it denoised
    std::vector<double> display_seconds;  // per image shown: its tone map and texture upload, on the interface thread
    std::vector<double> display_pixels;   // ... and its pixels
};

// The q-quantile (0..1) by the nearest rank; 0 when empty.
double quantile(std::vector<double> values, double q);

// Lines for the terminal: frames, median and p95 frame time in ms and frames/s, the changes' latency
// (median, p95, max), the cost of showing an image (median per image and per pixel).
std::string describe(const FrameStats& stats);

}  // namespace lab::viewer
