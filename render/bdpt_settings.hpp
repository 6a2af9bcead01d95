// The settings only the bidirectional integrators read (bdpt, lt: kernels/bdpt.h), and the views
// into their strategies for looking at the estimator rather than rendering an image.
#pragma once

namespace lab::render {

// BDPT's multiple importance sampling heuristic (its command-line words: render/render_settings.hpp).
enum class MisHeuristic { balance, power };

struct BdptSettings {
    MisHeuristic mis_heuristic = MisHeuristic::balance;
    // bdpt-cache (kernels/bdpt_cache.h, render/light_cache.hpp): light subpaths per sample index, as
    // a multiple of the image's pixels (--light-paths), and the cache vertices each camera vertex is
    // joined to (--connections). The defaults are measured (docs/bdpt.md, "The light-vertex cache").
    float light_paths = 0.25f;
    int connections = 1;
    // bdpt, lt, bdpt-cache: a connection whose MIS weight is below this traces its visibility march
    // with probability weight / connection_roulette (--connection-roulette; 0: always). Measured in
    // docs/bdpt.md, "Connection roulette".
    float connection_roulette = 0.0f;
    // vcm (kernels/vcm.h, render/vcm.hpp): the first sample's merge radius r_0, in scene units
    // (--merge-radius); 0: a share of the scene's bounding radius.
    float merge_radius = 0.0f;
};

// The strategies apart (--strategies DIR, the tests of the estimator): other masks than the
// integrator's, one strategy alone, a strategy without its MIS weight.
struct StrategyDebugSettings {
    int strategies = 0;                    // a STRATEGY_* mask of kernels/bdpt_settings.h; 0: the integrator's own
    int strategy_s = -1, strategy_t = -1;  // >= 0: only the strategy (s, t)
    bool strategy_unweighted = false;      // with strategy_s: without its MIS weight
};

}  // namespace lab::render
