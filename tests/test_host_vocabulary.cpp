// The host's stand-ins for OpenCL built-ins that single_source/host_vocabulary.hpp writes itself
// instead of taking from <cmath>: they must give libm's bits, or the host BRDF would drift from
// what it computed before (energy tables, chi-square, the OpenCL agreement's reference).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "single_source/host_vocabulary.hpp"
#include "tests/float_bits.hpp"

namespace {

// Every pair of these: NaN, both zeros, infinities, a denormal, ordinary and equal values.
std::vector<float> operands() {
    const float inf = std::numeric_limits<float>::infinity();
    return {std::nanf(""), -std::nanf(""), 0.0f, -0.0f, inf, -inf, 1e-40f, -1e-40f, 1.0f, -1.0f, 2.5f, 1.0f, -3e38f};
}

}  // namespace

TEST_CASE("fmax and fmin give libm's bits, NaN and signed zeros included", "[vocabulary]") {
    const std::vector<float> v = operands();
    int pairs = 0;
    for (float a : v) {
        for (float b : v) {
            INFO("a = " << a << " (bits " << float_bits(a) << "), b = " << b << " (bits " << float_bits(b) << ")");
            float max_libm = std::fmax(a, b), min_libm = std::fmin(a, b);
            float max_here = single_source::fmax(a, b), min_here = single_source::fmin(a, b);
            // a NaN result: any NaN (libm does not promise which one's payload)
            if (std::isnan(max_libm)) CHECK(std::isnan(max_here));
            else CHECK(float_bits(max_here) == float_bits(max_libm));
            if (std::isnan(min_libm)) CHECK(std::isnan(min_here));
            else CHECK(float_bits(min_here) == float_bits(min_libm));
            ++pairs;
        }
    }
    CHECK(pairs == 169);
}
