// Which of BDPT's strategies carries which light, grouped by the integrator that has the strategy
// too: the stability atlas's integrator entry (docs/report.md). With the balance heuristic a
// strategy's MIS weight is its density over the sum of every strategy's density for the same path
// (Veach 1997, section 9.2.2), so the share of a pixel's light that a group's weighted renders carry
// is the share of its sampling density there: where the path tracer's strategies carry under a
// tenth, the other strategies sample that light at least nine times as densely.
#pragma once

#include <array>
#include <vector>

#include "film/image.hpp"

namespace lab::report {

// The path tracer's strategies: s <= 1 light vertices (s = 0, a camera path that reaches a light;
// s = 1, next-event estimation); light tracing's: t = 1 camera vertex (a light path seen by the
// lens); BDPT's alone: both subpaths of two or more vertices, joined by a connection.
enum class StrategyGroup { path_tracer = 0, connection = 1, light_tracer = 2 };
constexpr int kStrategyGroups = 3;

StrategyGroup strategy_group(int s, int t);
const char* strategy_group_name(StrategyGroup group);  // "the path tracer's (s <= 1)", ...

// One strategy's render, weighted by its MIS weight with the balance heuristic.
struct WeightedStrategy {
    int s = 0, t = 0;
    film::ImageRgb image;
};

struct StrategyLight {
    int s = 0, t = 0;
    double share = 0.0;  // of the image's luminance
};

struct StrategyShares {
    film::ImageRgb image;   // the strategies' sum: the BDPT image
    film::ImageRgb groups;  // per pixel the groups' shares of its luminance: red light tracing's, green connections', blue the path tracer's; black where unlit
    std::array<double, kStrategyGroups> light{};  // each group's share of the image's luminance (index: StrategyGroup)
    // of the lit pixels, the share where the group carries less than `minor` of the pixel's light
    std::array<double, kStrategyGroups> minor_pixels{};
    double lit_pixels = 0.0;                // the share of pixels lit: luminance above `unlit` times the image's mean
    std::vector<StrategyLight> strategies;  // every strategy's share, in the order given
};

// Throws std::invalid_argument for no strategies, images of different sizes, a strategy outside
// s >= 0, t >= 1, s + t >= 2, or a negative or non-finite pixel.
StrategyShares strategy_shares(const std::vector<WeightedStrategy>& strategies, double minor = 0.1, double unlit = 0.01);

}  // namespace lab::report
