// The single-source vocabulary on the host: namespace single_source.
//
// Maps the OpenCL C vocabulary used by the single-source headers (brdf/, sdf/, ibl/, kernels/*.h)
// onto GLM and <cmath>, so the very same .h files compile as C++ on the host, then includes
// single_source/vocabulary.h (SS_FN, sqr, float3_splat, ...) in the same namespace. Only what those
// headers use is mapped; swizzles (.xy) are not, so the headers build vectors with make_floatN().
// A module's host header (brdf/brdf.hpp, sdf/sdf.hpp, ibl/ibl.hpp) includes this first and its own
// headers inside its namespace with `using namespace single_source;`; the vocabulary's include
// guard keeps it here.
#pragma once

#include <cmath>
#include <glm/glm.hpp>

namespace single_source {

using float2 = glm::vec2;
using float3 = glm::vec3;
using float4 = glm::vec4;
using uint = unsigned int;
using ushort = unsigned short;

// Float overloads from <cmath>: without these, C's double versions would be picked and the
// host would compute in a different precision than the OpenCL build.
using std::acos;
using std::asin;
using std::atan;
using std::atan2;
using std::cos;
using std::exp;
using std::exp2;
using std::fmod;
using std::log2;
using std::round;
using std::tan;
using std::fabs;
using std::ceil;
using std::floor;
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

inline float2 make_float2(float x, float y) { return float2(x, y); }
inline float3 make_float3(float x, float y, float z) { return float3(x, y, z); }
inline float4 make_float4(float x, float y, float z, float w) { return float4(x, y, z, w); }
// fmax and fmin as glibc computes them (a NaN argument loses; of two equal values, signed zeros
// included, the second), inline: GCC does not expand std::fmax without -ffinite-math-only and calls
// libm through the PLT, 6 % of a Hyper-Cauchy chi-square's time.
inline float fmax(float a, float b) { return a > b || b != b ? a : b; }
inline float fmin(float a, float b) { return a < b || b != b ? a : b; }

// OpenCL's component-wise vector built-ins.
inline float2 fabs(float2 v) { return glm::abs(v); }
inline float3 fabs(float3 v) { return glm::abs(v); }
inline float2 fmax(float2 a, float2 b) { return glm::max(a, b); }
inline float3 fmax(float3 a, float3 b) { return glm::max(a, b); }
inline float2 fmin(float2 a, float2 b) { return glm::min(a, b); }
inline float3 fmin(float3 a, float3 b) { return glm::min(a, b); }
inline float3 floor(float3 v) { return glm::floor(v); }
inline float3 round(float3 v) { return glm::round(v); }
inline float sign(float x) { return x > 0.0f ? 1.0f : (x < 0.0f ? -1.0f : 0.0f); }
inline int min(int a, int b) { return a < b ? a : b; }
inline int max(int a, int b) { return a > b ? a : b; }
inline uint min(uint a, uint b) { return a < b ? a : b; }
inline uint max(uint a, uint b) { return a > b ? a : b; }
// OpenCL defines mix(x, y, a) as x + (y - x) a; glm::mix computes x (1 - a) + y a, which rounds
// differently, so the host would not match the kernels.
// OpenCL's sinpi(x) = sin(pi x) and cospi(x): the product pi x is not rounded first
inline float sinpi(float x) { return float(std::sin(3.14159265358979323846 * double(x))); }
inline float cospi(float x) { return float(std::cos(3.14159265358979323846 * double(x))); }
inline float mix(float x, float y, float a) { return x + (y - x) * a; }
inline float3 mix(float3 x, float3 y, float a) { return x + (y - x) * a; }
inline float4 mix(float4 x, float4 y, float a) { return x + (y - x) * a; }
inline bool isfinite_f(float x) { return std::isfinite(x); }
// OpenCL's select(a, b, c): c ? b : a for scalars.
inline float select(float a, float b, int c) { return c ? b : a; }
inline int select(int a, int b, int c) { return c ? b : a; }


#include "single_source/vocabulary.h"

}  // namespace single_source
