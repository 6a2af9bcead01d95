#include "common/ffmpeg.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "common/child_process.hpp"

namespace lab {

bool ffmpeg_available() { return run_process({"ffmpeg", "-version"}, "/dev/null") == 0; }

void encode_video(const std::string& frame_pattern, long long first_frame, double fps, const std::string& output, const std::string& log) {
    char rate[40];
    std::snprintf(rate, sizeof rate, "%.10g", fps);
    const std::string partial = output + ".partial.mp4";
    const int status = run_process({"ffmpeg", "-y", "-loglevel", "error", "-framerate", rate, "-start_number", std::to_string(first_frame), "-i",
                                    frame_pattern, "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf",
                                    "18", partial},
                                   log);
    std::error_code ec;
    if (status != 0) {
        std::filesystem::remove(partial, ec);
        throw std::runtime_error("ffmpeg failed (status " + std::to_string(status) + "): " + last_line(log));
    }
    std::filesystem::rename(partial, output);
}

}  // namespace lab
