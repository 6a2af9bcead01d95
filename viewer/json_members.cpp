#include "viewer/json_members.hpp"

#include <nlohmann/json.hpp>

namespace lab::viewer {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

size_t skip_space(const std::string& t, size_t i) {
    while (i < t.size() && is_space(t[i])) ++i;
    return i;
}

// One past the string whose opening quote is at i; npos when it does not end.
size_t skip_string(const std::string& t, size_t i) {
    for (++i; i < t.size(); ++i) {
        if (t[i] == '\\') ++i;
        else if (t[i] == '"') return i + 1;
    }
    return std::string::npos;
}

// One past the value that starts at i (strings, nested objects and arrays, literals and numbers);
// npos when it does not end. Well-formedness beyond the nesting is the parser's to check.
size_t skip_value(const std::string& t, size_t i) {
    if (i >= t.size()) return std::string::npos;
    if (t[i] == '"') return skip_string(t, i);
    if (t[i] == '{' || t[i] == '[') {
        int depth = 0;
        while (i < t.size()) {
            const char c = t[i];
            if (c == '"') {
                i = skip_string(t, i);
                if (i == std::string::npos) return i;
                continue;
            }
            if (c == '{' || c == '[') ++depth;
            if (c == '}' || c == ']') {
                if (--depth == 0) return i + 1;
            }
            ++i;
        }
        return std::string::npos;
    }
    while (i < t.size() && !is_space(t[i]) && t[i] != ',' && t[i] != '}' && t[i] != ']') ++i;
    return i;
}

}  // namespace

std::optional<JsonObjectSpan> json_object_at(const std::string& t, size_t from) {
    JsonObjectSpan span;
    size_t i = skip_space(t, from);
    if (i >= t.size() || t[i] != '{') return std::nullopt;
    span.open = i;
    i = skip_space(t, i + 1);
    if (i < t.size() && t[i] == '}') {
        span.close = i;
        return span;
    }
    for (;;) {
        if (i >= t.size() || t[i] != '"') return std::nullopt;
        JsonMember m;
        m.key_begin = i;
        const size_t key_end = skip_string(t, i);
        if (key_end == std::string::npos) return std::nullopt;
        try {
            m.key = nlohmann::json::parse(t.substr(i, key_end - i)).get<std::string>();
        } catch (const nlohmann::json::exception&) {
            return std::nullopt;
        }
        i = skip_space(t, key_end);
        if (i >= t.size() || t[i] != ':') return std::nullopt;
        m.value_begin = skip_space(t, i + 1);
        m.value_end = skip_value(t, m.value_begin);
        if (m.value_end == std::string::npos || m.value_end == m.value_begin) return std::nullopt;
        span.members.push_back(m);
        i = skip_space(t, m.value_end);
        if (i < t.size() && t[i] == ',') {
            i = skip_space(t, i + 1);
            continue;
        }
        if (i < t.size() && t[i] == '}') {
            span.close = i;
            return span;
        }
        return std::nullopt;
    }
}

std::optional<std::string> json_line_indent(const std::string& t, size_t position) {
    size_t start = position;
    while (start > 0 && (t[start - 1] == ' ' || t[start - 1] == '\t')) --start;
    if (start > 0 && t[start - 1] != '\n') return std::nullopt;
    return t.substr(start, position - start);
}

}  // namespace lab::viewer
