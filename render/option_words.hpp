// The command line's words for an enum's values: a table of (word, value) pairs, the first word of a
// value its name and any later ones synonyms.
#pragma once

#include <string>

#include "common/input_error.hpp"

namespace lab::render {

// The value of `text`; a lab::InputError naming `option` and every word otherwise.
template <typename Words>
auto parse_word(const std::string& text, const std::string& option, const Words& words) {
    std::string known;
    for (const auto& [word, value] : words) {
        if (text == word) return value;
        known += std::string(known.empty() ? "" : ", ") + word;
    }
    throw InputError(option, "", "unknown value \"" + text + "\" (" + known + ")");
}

template <typename Enum, typename Words>
const char* word_of(Enum value, const Words& words) {
    for (const auto& [word, v] : words)
        if (v == value) return word;
    return "?";
}

}  // namespace lab::render
