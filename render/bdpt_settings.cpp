#include "render/bdpt_settings.hpp"

#include <utility>

#include "render/option_words.hpp"

namespace lab::render {

namespace {

constexpr std::pair<const char*, MisHeuristic> kMisWords[] = {{"balance", MisHeuristic::balance}, {"power", MisHeuristic::power}};

}  // namespace

MisHeuristic parse_mis_heuristic(const std::string& text, const std::string& option) { return parse_word(text, option, kMisWords); }
const char* mis_heuristic_name(MisHeuristic heuristic) { return word_of(heuristic, kMisWords); }

}  // namespace lab::render
