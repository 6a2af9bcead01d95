// Reading a scene file's JSON with a field path for every complaint: the document parser (line and
// column of a syntax error, the field of a number overflow, duplicate keys) and typed readers of
// one JSON object's fields that reject unknown keys, wrong types, non-finite and out-of-range values.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"

namespace lab::scene {

// Key order matters: material slots are numbered in file order.
using Json = nlohmann::ordered_json;

// "a.b" / "b" at the top; "a[3]".
std::string field_path(const std::string& parent, const std::string& key);
std::string element_path(const std::string& parent, size_t index);

// Throws lab::InputError(file, field, ...) for malformed JSON ("malformed JSON at line L, column C:
// ..."), a number that overflows a double, or a key given twice in one object.
Json parse_json_document(const std::string& text, const std::string& file);

// A value for messages: "%.7g", all a float holds without the noise of its binary expansion.
std::string format_number(double value);

// One JSON object of the scene file, at `path`. The constructor rejects a non-object and any key
// outside `allowed`; the readers name `path.key` in their errors.
class Fields {
public:
    Fields(const Json& value, std::string path, std::string file, std::vector<std::string> allowed);

    bool has(const std::string& key) const;
    const Json& at(const std::string& key) const;  // throws "missing required key"
    std::string path_of(const std::string& key) const { return field_path(path_, key); }
    const std::string& path() const { return path_; }
    const std::string& file() const { return file_; }

    std::string string(const std::string& key) const;
    float number(const std::string& key) const;           // any finite float
    float positive(const std::string& key) const;         // > 0
    float non_negative(const std::string& key) const;     // >= 0
    float in_range(const std::string& key, float lo, float hi) const;          // lo <= v <= hi
    float in_open_range(const std::string& key, float lo, float hi) const;     // lo < v < hi
    Vec3 vec3(const std::string& key) const;              // 3 finite floats
    Vec3 positive_vec3(const std::string& key) const;     // each > 0
    Vec3 non_negative_vec3(const std::string& key) const; // each >= 0
    Vec3 nonzero_vec3(const std::string& key) const;      // not (0, 0, 0)
    Vec3 integer_vec3(const std::string& key, int magnitude_max) const;  // 3 integers, |n| <= magnitude_max

    [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

private:
    const Json& value_;
    std::string path_;
    std::string file_;
};

// A finite number that fits a float, at `path`; throws otherwise.
float read_float(const Json& value, const std::string& file, const std::string& path);

}  // namespace lab::scene
