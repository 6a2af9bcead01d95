#include "viewer/frame_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lab::viewer {

double quantile(std::vector<double> values, double q) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    size_t rank = size_t(std::ceil(q * double(values.size())));
    return values[rank == 0 ? 0 : std::min(rank, values.size()) - 1];
}

std::string describe(const FrameStats& s) {
    char line[512];
    double median = quantile(s.frame_seconds, 0.5), p95 = quantile(s.frame_seconds, 0.95);
    std::snprintf(line, sizeof line, "interface: %zu frames, median %.1f ms (%.1f frames/s), p95 %.1f ms\n", s.frame_seconds.size(),
                  median * 1e3, median > 0.0 ? 1.0 / median : 0.0, p95 * 1e3);
    std::string out = line;
    // the changes' latency to a frame that shows them, when there were any
    const auto latency = [&](const char* frame, const std::vector<double>& seconds) {
        if (seconds.empty()) return;
        std::snprintf(line, sizeof line, "change to first %s frame: %zu changes, median %.1f ms, p95 %.1f ms, max %.1f ms\n", frame,
                      seconds.size(), quantile(seconds, 0.5) * 1e3, quantile(seconds, 0.95) * 1e3, quantile(seconds, 1.0) * 1e3);
        out += line;
    };
    latency("updated", s.change_seconds);
    latency("denoised", s.denoised_seconds);
    if (!s.display_seconds.empty()) {
        std::vector<double> per_pixel;
        for (size_t i = 0; i < s.display_seconds.size(); ++i) per_pixel.push_back(s.display_seconds[i] / std::max(1.0, s.display_pixels[i]));
        std::snprintf(line, sizeof line, "display: %zu images shown, median %.2f ms each (%.1f ns per pixel: tone map and upload)\n",
                      s.display_seconds.size(), quantile(s.display_seconds, 0.5) * 1e3, quantile(per_pixel, 0.5) * 1e9);
        out += line;
    }
    return out;
}

}  // namespace lab::viewer
