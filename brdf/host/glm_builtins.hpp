// Maps the OpenCL C vocabulary used by the single-source BRDF headers onto GLM and <cmath>,
// so the very same .h files compile as C++ on the host. Only what brdf/*.h uses is mapped.
#pragma once

#include <cmath>
#include <glm/glm.hpp>

namespace brdf {

using float3 = glm::vec3;

// Float overloads from <cmath>: without these, C's double versions would be picked and the
// host would compute in a different precision than the OpenCL build.
using std::acos;
using std::atan2;
using std::cos;
using std::exp;
using std::fabs;
using std::floor;
using std::fmax;
using std::fmin;
using std::lgamma;
using std::log;
using std::pow;
using std::sin;
using std::sqrt;

using glm::clamp;
using glm::cross;
using glm::dot;
using glm::length;
using glm::normalize;

inline float3 make_float3(float x, float y, float z) { return float3(x, y, z); }
// OpenCL defines mix(x, y, a) as x + (y - x) a; glm::mix computes x (1 - a) + y a, which rounds
// differently, so the host would not match the kernels.
inline float mix(float x, float y, float a) { return x + (y - x) * a; }
inline float3 mix(float3 x, float3 y, float a) { return x + (y - x) * a; }
inline bool isfinite_f(float x) { return std::isfinite(x); }

}  // namespace brdf
