// A frame pattern: a path with one printf-style integer conversion, %d or %0Nd, that a frame number
// fills in (out_%04d.exr holds frame 7 in out_0007.exr); %% is a percent sign. Sequences of renders
// write their frames by one, FFmpeg reads them back by the same, and the turntable writes its own.
#pragma once

#include <string>

namespace lab {

// Whether `pattern` has exactly one %d or %0Nd and no other conversion.
bool is_frame_pattern(const std::string& pattern);

// Throws lab::InputError(pattern, "", ...) unless is_frame_pattern: `what` says what the pattern is
// for ("the sequence's output"), and the message how many conversions it has.
void check_frame_pattern(const std::string& pattern, const std::string& what);

// The path of frame `frame` (>= 0): the conversion replaced by the number, zero-padded to N digits
// for %0Nd, and each %% by %. The pattern must be one (is_frame_pattern).
std::string frame_path(const std::string& pattern, long long frame);

}  // namespace lab
