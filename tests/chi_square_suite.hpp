// The options of the BSDF chi-square suite (tests/test_chi_square.cpp), shared with the tests that
// show its power (tests/test_chi_square_checks.cpp).
//
// Samples per test: 500 000 over 100 x 100 equal-area cells, 50 expected per cell on average. The
// stated power, measured at this count: a pdf 10 % off on half the sphere adds 1090 to the statistic
// at about 4900 degrees of freedom (p = 5e-25), six standard deviations of the statistic past the
// suite's Sidak level, so it is rejected with probability above 0.999; a roughness 10 % off adds
// 24 000. test_chi_square_checks.cpp checks both at this count.
#pragma once

#include "validation/chi_square.hpp"

constexpr long kChiSquareSuiteSamples = 500000;
constexpr int kChiSquareSuiteTests = 25 * 5;  // settings x incident directions; test_chi_square.cpp checks the count

inline lab::validation::ChiSquareOptions chi_square_suite_options() {
    lab::validation::ChiSquareOptions options;
    options.samples = kChiSquareSuiteSamples;
    options.tests = kChiSquareSuiteTests;
    return options;
}
