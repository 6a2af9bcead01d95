#include "scene/json_fields.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "common/input_error.hpp"
#include "scene/scene_limits.hpp"

namespace lab::scene {

std::string field_path(const std::string& parent, const std::string& key) { return parent.empty() ? key : parent + "." + key; }

std::string element_path(const std::string& parent, size_t index) { return parent + "[" + std::to_string(index) + "]"; }

std::string format_number(double value) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.7g", value);
    return text;
}

namespace {

// Where the parser is, for messages: one frame per open object or array.
struct Frame {
    bool array = false;
    size_t index = 0;            // arrays: the element being read
    std::string key;             // objects: the last key read
    std::set<std::string> keys;  // objects: every key read so far
};

std::string current_path(const std::vector<Frame>& frames) {
    std::string path;
    for (const Frame& f : frames) {
        if (f.array)
            path = element_path(path, f.index);
        else if (!f.key.empty())
            path = field_path(path, f.key);
    }
    return path;
}

// nlohmann's text after its "[json.exception.x.n] " tag, and after "parse error " for syntax errors.
std::string strip_tag(const std::string& what) {
    std::string text = what;
    auto pos = text.find("] ");
    if (pos != std::string::npos) text = text.substr(pos + 2);
    const std::string parse_error = "parse error ";
    if (text.rfind(parse_error, 0) == 0) text = text.substr(parse_error.size());
    return text;
}

}  // namespace

Json parse_json_document(const std::string& text, const std::string& file) {
    std::vector<Frame> frames;
    auto element_done = [&frames]() {
        if (!frames.empty() && frames.back().array) ++frames.back().index;
    };
    auto callback = [&](int, Json::parse_event_t event, Json& value) {
        if ((event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) && frames.size() >= kMaxJsonNesting)
            throw InputError(file, current_path(frames),
                             "nested more than " + std::to_string(kMaxJsonNesting) + " objects and arrays deep (the limit of a scene file)");
        switch (event) {
        case Json::parse_event_t::object_start: frames.push_back(Frame{}); break;
        case Json::parse_event_t::array_start: frames.push_back(Frame{true, 0, {}, {}}); break;
        case Json::parse_event_t::key: {
            Frame& f = frames.back();
            f.key = value.get<std::string>();
            if (!f.keys.insert(f.key).second) throw InputError(file, current_path(frames), "duplicate key");
            break;
        }
        case Json::parse_event_t::value: element_done(); break;
        case Json::parse_event_t::object_end:
        case Json::parse_event_t::array_end:
            frames.pop_back();
            element_done();
            break;
        }
        return true;
    };
    try {
        return Json::parse(text, callback);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(file, current_path(frames), "malformed JSON " + strip_tag(e.what()));
    } catch (const nlohmann::json::exception& e) {  // number overflow such as 1e999
        throw InputError(file, current_path(frames), "malformed JSON: " + strip_tag(e.what()));
    }
}

float read_float(const Json& value, const std::string& file, const std::string& path) {
    if (!value.is_number()) throw InputError(file, path, std::string("expected a number, got ") + value.type_name());
    double v = value.get<double>();
    if (!std::isfinite(v)) throw InputError(file, path, "value is not a finite number");
    if (std::fabs(v) > double(FLT_MAX)) throw InputError(file, path, "value " + format_number(v) + " overflows a 32-bit float");
    return float(v);
}

Fields::Fields(const Json& value, std::string path, std::string file, std::vector<std::string> allowed)
    : value_(value), path_(std::move(path)), file_(std::move(file)) {
    if (!value_.is_object()) throw InputError(file_, path_, std::string("expected an object, got ") + value_.type_name());
    for (auto it = value_.begin(); it != value_.end(); ++it) {
        bool known = false;
        for (const std::string& a : allowed) known = known || a == it.key();
        if (known) continue;
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        throw InputError(file_, path_of(it.key()), "unknown key (expected one of: " + list + ")");
    }
}

void Fields::fail(const std::string& key, const std::string& problem) const { throw InputError(file_, path_of(key), problem); }

bool Fields::has(const std::string& key) const { return value_.contains(key); }

const Json& Fields::at(const std::string& key) const {
    if (!has(key)) throw InputError(file_, path_of(key), "missing required key");
    return value_.at(key);
}

std::string Fields::string(const std::string& key) const {
    const Json& v = at(key);
    if (!v.is_string()) fail(key, std::string("expected a string, got ") + v.type_name());
    return v.get<std::string>();
}

float Fields::number(const std::string& key) const { return read_float(at(key), file_, path_of(key)); }

float Fields::positive(const std::string& key) const {
    float v = number(key);
    if (!(v > 0.0f)) fail(key, "value " + format_number(v) + " must be > 0");
    return v;
}

float Fields::non_negative(const std::string& key) const {
    float v = number(key);
    if (!(v >= 0.0f)) fail(key, "value " + format_number(v) + " must be >= 0");
    return v;
}

float Fields::in_range(const std::string& key, float lo, float hi) const {
    float v = number(key);
    if (!(v >= lo && v <= hi))
        fail(key, "value " + format_number(v) + " is out of range [" + format_number(lo) + ", " + format_number(hi) + "]");
    return v;
}

float Fields::in_open_range(const std::string& key, float lo, float hi) const {
    float v = number(key);
    if (!(v > lo && v < hi))
        fail(key, "value " + format_number(v) + " is out of range (" + format_number(lo) + ", " + format_number(hi) + ")");
    return v;
}

Vec3 Fields::vec3(const std::string& key) const {
    const Json& v = at(key);
    if (!v.is_array() || v.size() != 3) fail(key, "expected an array of 3 numbers");
    Vec3 out;
    for (int c = 0; c < 3; ++c) out[c] = read_float(v.at(size_t(c)), file_, element_path(path_of(key), size_t(c)));
    return out;
}

Vec3 Fields::positive_vec3(const std::string& key) const {
    Vec3 v = vec3(key);
    for (int c = 0; c < 3; ++c)
        if (!(v[c] > 0.0f)) throw InputError(file_, element_path(path_of(key), size_t(c)), "value " + format_number(v[c]) + " must be > 0");
    return v;
}

Vec3 Fields::non_negative_vec3(const std::string& key) const {
    Vec3 v = vec3(key);
    for (int c = 0; c < 3; ++c)
        if (!(v[c] >= 0.0f))
            throw InputError(file_, element_path(path_of(key), size_t(c)), "value " + format_number(v[c]) + " must be >= 0");
    return v;
}

Vec3 Fields::nonzero_vec3(const std::string& key) const {
    Vec3 v = vec3(key);
    if (v.x == 0.0f && v.y == 0.0f && v.z == 0.0f) fail(key, "must not be the zero vector");
    return v;
}

Vec3 Fields::integer_vec3(const std::string& key, int magnitude_max) const {
    const Json& v = at(key);
    if (!v.is_array() || v.size() != 3) fail(key, "expected an array of 3 integers");
    Vec3 out;
    for (int c = 0; c < 3; ++c) {
        const Json& n = v.at(size_t(c));
        std::string path = element_path(path_of(key), size_t(c));
        if (!n.is_number_integer())
            throw InputError(file_, path, "expected an integer, got " + (n.is_number() ? format_number(n.get<double>()) : std::string(n.type_name())));
        long long i = n.get<long long>();
        if (i < -magnitude_max || i > magnitude_max)
            throw InputError(file_, path, "value " + std::to_string(i) + " is out of range [" + std::to_string(-magnitude_max) + ", " +
                                              std::to_string(magnitude_max) + "]");
        out[c] = float(i);
    }
    return out;
}

}  // namespace lab::scene
