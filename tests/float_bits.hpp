// A float's bit pattern, for tests that compare results bit for bit (C++17 has no std::bit_cast).
#pragma once

#include <cstdint>
#include <cstring>

inline uint32_t float_bits(float v) {
    uint32_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}
