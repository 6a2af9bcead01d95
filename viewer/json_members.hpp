// Where the members of a JSON object lie in its text, so that "export to scene" can replace or add
// one material and leave every other byte of the scene file as it was (nlohmann-json 3.11 parses
// and dumps whole documents, without source positions). Only spans are found here; the caller
// checks the edited text by parsing it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lab::viewer {

struct JsonMember {
    std::string key;           // unescaped
    size_t key_begin = 0;      // the key's opening quote
    size_t value_begin = 0;    // the value's first character
    size_t value_end = 0;      // one past its last
};

struct JsonObjectSpan {
    size_t open = 0, close = 0;  // the braces
    std::vector<JsonMember> members;
};

// The object whose '{' is the first non-space character at or after `from`; none when the text there
// is not a well-formed object (the caller then falls back to rewriting the whole document).
std::optional<JsonObjectSpan> json_object_at(const std::string& text, size_t from);

// The spaces and tabs before `position` on its line when nothing else precedes it there; none
// otherwise.
std::optional<std::string> json_line_indent(const std::string& text, size_t position);

}  // namespace lab::viewer
