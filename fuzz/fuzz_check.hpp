// What a fuzz harness does when an invariant breaks: print what broke and abort, which libFuzzer
// records as a crash (with the input) and the corpus replay reports as a failed test.
#pragma once

#include <cstdio>
#include <cstdlib>

#define FUZZ_REQUIRE(condition, what)                                                               \
    do {                                                                                          \
        if (!(condition)) {                                                                       \
            std::fprintf(stderr, "fuzz invariant broken at %s:%d: %s\n", __FILE__, __LINE__, what); \
            std::abort();                                                                         \
        }                                                                                         \
    } while (0)
