// Deterministic uniform numbers for the validation checks: one seeded stream per chunk of work,
// so results do not depend on how many threads share the chunks.
#pragma once

#include <cstdint>
#include <random>

#include "brdf/brdf.hpp"

namespace lab::validation {

// splitmix64 finaliser: decorrelates seeds that differ in a few bits (seed + chunk index).
inline uint64_t mix_seed(uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

class UniformRandom {
public:
    explicit UniformRandom(uint64_t seed) : engine_(mix_seed(seed)) {}

    // In [0, 1), never 1: the top 24 bits fill a float's mantissa exactly.
    float next_float() { return float(engine_() >> 40) * 0x1.0p-24f; }
    double next_double() { return double(engine_() >> 11) * 0x1.0p-53; }
    float uniform(float lo, float hi) { return lo + (hi - lo) * next_float(); }
    brdf::float3 next_float3() {
        float x = next_float(), y = next_float();
        return brdf::float3(x, y, next_float());
    }
    uint64_t next_bits() { return engine_(); }

private:
    std::mt19937_64 engine_;
};

}  // namespace lab::validation
