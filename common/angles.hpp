// Degrees to radians in the host code (the single-source code has SS_PI).
#pragma once

namespace lab {

inline constexpr float kRadiansPerDegree = 3.14159265358979323846f / 180.0f;

}  // namespace lab
