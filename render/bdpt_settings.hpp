// The settings only the bidirectional integrators read (bdpt, lt: kernels/bdpt.h), and the views
// into their strategies for looking at the estimator rather than rendering an image.
#pragma once

#include <string>

namespace lab::render {

// BDPT's multiple importance sampling heuristic.
enum class MisHeuristic { balance, power };

// Parse the command-line word; errors are lab::InputError naming `option`.
MisHeuristic parse_mis_heuristic(const std::string& text, const std::string& option = "--mis");
const char* mis_heuristic_name(MisHeuristic heuristic);

struct BdptSettings {
    MisHeuristic mis_heuristic = MisHeuristic::balance;
};

// The strategies apart (--strategies DIR, the tests of the estimator): other masks than the
// integrator's, one strategy alone, a strategy without its MIS weight.
struct StrategyDebugSettings {
    int strategies = 0;                    // a STRATEGY_* mask of kernels/bdpt_settings.h; 0: the integrator's own
    int strategy_s = -1, strategy_t = -1;  // >= 0: only the strategy (s, t)
    bool strategy_unweighted = false;      // with strategy_s: without its MIS weight
};

}  // namespace lab::render
