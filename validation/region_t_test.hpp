// Two renderers compared region by region with Welch's t-test (validation/welch_t_test.hpp): each
// gives several independent renders of the same image (other seeds or sample ranges); the mean of
// a region in one render is one estimate, so each region has as many estimates per renderer as
// renders. A renderer with a bias somewhere shows as a region whose means differ by more than their
// noise allows. Needs no converged reference. Paired: render i of each renderer drew the same
// random numbers (same seed and sample range), so the noise they share (a camera ray's jitter
// across a light's edge) cancels in the paired t-test of their differences.
#pragma once

#include <vector>

#include "film/image.hpp"
#include "validation/welch_t_test.hpp"

namespace lab::validation {

struct RegionTest {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) x [y0, y1)
    int channel = 0;                     // 0, 1, 2: r, g, b
    WelchResult result;
};

struct RegionComparison {
    std::vector<RegionTest> regions;  // every region and channel
    double level = 0.0;               // the per-test level (Sidak-corrected from the family's)
    int rejected = 0;                 // regions whose p-value is below `level`
    const RegionTest* worst() const;  // the smallest p-value
};

// The detection probability at which detectable_difference states a comparison's power.
constexpr double kDetectionProbability = 0.9;

// The smallest difference |mean_a - mean_b| that region r's test rejects at the per-test `level`
// (RegionComparison::level) with probability kDetectionProbability, relative to |mean_b|: in r's
// standard errors, its critical t plus that probability's normal quantile scaled by the spread of
// the noncentral t there (Jennett and Welch's approximation). Infinite where mean_b is 0 and the
// noise is not.
double detectable_difference(const RegionTest& r, double level);

// The largest detectable_difference over the comparison's regions and channels.
double detectable_difference(const RegionComparison& c);

enum class Pairing { independent, paired };

// Splits the image into `columns` x `rows` regions and tests each channel's region mean of `a`
// against that of `b` at a family-wise level `significance` over all regions and channels, by
// Welch's test or, paired, by the paired t-test (as many renders of each). Every image has the
// same size; at least two of each.
RegionComparison compare_by_region(const std::vector<film::ImageRgb>& a, const std::vector<film::ImageRgb>& b, int columns, int rows,
                                   double significance, Pairing pairing = Pairing::independent);

}  // namespace lab::validation
