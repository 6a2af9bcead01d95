#include "scene/keyframes.hpp"

#include <algorithm>

#include "common/input_error.hpp"
#include "scene/json_fields.hpp"

namespace lab::scene {

const Track* Keyframes::find(const std::string& name) const {
    for (const Track& track : tracks)
        if (track.name == name) return &track;
    return nullptr;
}

namespace {

double value_at(const Track& track, size_t key, int component) { return double(track.values[key * size_t(track.components) + size_t(component)]); }

// The Catmull-Rom tangent at keyframe k (Interpolation::catmull_rom): the central difference over
// its neighbours, one-sided at the ends.
double tangent(const std::vector<float>& times, const Track& track, int component, size_t k) {
    const size_t lo = k == 0 ? 0 : k - 1, hi = k + 1 == times.size() ? k : k + 1;
    return (value_at(track, hi, component) - value_at(track, lo, component)) / (double(times[hi]) - double(times[lo]));
}

int minimum_keyframes(Interpolation interpolation) { return interpolation == Interpolation::catmull_rom ? 3 : 2; }

}  // namespace

double interpolate(const std::vector<float>& times, const Track& track, int component, Interpolation interpolation, double t) {
    const size_t n = times.size();
    if (!(t > double(times.front()))) return value_at(track, 0, component);
    if (!(t < double(times.back()))) return value_at(track, n - 1, component);
    // the segment [times[k], times[k + 1]) that holds t
    const size_t k = size_t(std::upper_bound(times.begin(), times.end(), t, [](double a, float b) { return a < double(b); }) - times.begin()) - 1;
    const double h = double(times[k + 1]) - double(times[k]), s = (t - double(times[k])) / h;
    const double p0 = value_at(track, k, component), p1 = value_at(track, k + 1, component);
    if (interpolation == Interpolation::linear) return p0 + s * (p1 - p0);
    // cubic Hermite basis on the segment, the tangents scaled by its length
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s, h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
    return h00 * p0 + h10 * h * tangent(times, track, component, k) + h01 * p1 + h11 * h * tangent(times, track, component, k + 1);
}

std::vector<double> track_value(const Keyframes& keyframes, const Track& track, double t) {
    std::vector<double> value(size_t(track.components));
    for (int c = 0; c < track.components; ++c) value[size_t(c)] = interpolate(keyframes.times, track, c, keyframes.interpolation, t);
    return value;
}

Keyframes parse_keyframes(const Json& value, const std::string& path, const std::string& file, const std::vector<TrackSpec>& specs) {
    std::vector<std::string> allowed = {"interpolation", "times"};
    for (const TrackSpec& spec : specs) allowed.push_back(spec.name);
    Fields f(value, path, file, allowed);
    Keyframes keyframes;
    keyframes.path = path;
    if (f.has("interpolation")) {
        const std::string word = f.string("interpolation");
        if (word == "catmull_rom")
            keyframes.interpolation = Interpolation::catmull_rom;
        else if (word != "linear")
            f.fail("interpolation", "unknown interpolation \"" + word + "\" (expected one of: linear, catmull_rom)");
    }
    const Json& times = f.at("times");
    if (!times.is_array()) f.fail("times", std::string("expected an array of times in seconds, got ") + times.type_name());
    const int needed = minimum_keyframes(keyframes.interpolation);
    if (times.size() < size_t(needed))
        f.fail("times", std::to_string(times.size()) + " keyframes, but " +
                            (keyframes.interpolation == Interpolation::catmull_rom ? "catmull_rom needs at least 3 (2 make a line: use linear)"
                                                                                   : "keyframes need at least 2 (one value is not animated: give it in place)"));
    for (size_t k = 0; k < times.size(); ++k) {
        const std::string at = element_path(f.path_of("times"), k);
        keyframes.times.push_back(read_float(times[k], file, at));
        if (k > 0 && !(keyframes.times[k] > keyframes.times[k - 1]))
            throw InputError(file, at, "time " + format_number(keyframes.times[k]) + " is not after the one before it (" +
                                           format_number(keyframes.times[k - 1]) + "): times must increase strictly");
    }
    for (const TrackSpec& spec : specs) {
        if (!f.has(spec.name)) continue;
        const Json& entries = f.at(spec.name);
        const std::string track_path = f.path_of(spec.name);
        if (!entries.is_array()) f.fail(spec.name, std::string("expected an array, one entry per time, got ") + entries.type_name());
        if (entries.size() != times.size())
            f.fail(spec.name, std::to_string(entries.size()) + " keyframes, but times has " + std::to_string(times.size()));
        Track track{spec.name, spec.components, {}};
        for (size_t k = 0; k < entries.size(); ++k) {
            const std::string entry_path = element_path(track_path, k);
            const Json& entry = entries[k];
            if (spec.components > 1 && (!entry.is_array() || entry.size() != size_t(spec.components)))
                throw InputError(file, entry_path, "expected an array of " + std::to_string(spec.components) + " numbers");
            for (int c = 0; c < spec.components; ++c) {
                const std::string number_path = spec.components > 1 ? element_path(entry_path, size_t(c)) : entry_path;
                const float v = read_float(spec.components > 1 ? entry[size_t(c)] : entry, file, number_path);
                const bool inside = spec.open ? (v > spec.lo && v < spec.hi) : (v >= spec.lo && v <= spec.hi);
                if (!inside)
                    throw InputError(file, number_path, "value " + format_number(v) + " is out of range " + (spec.open ? "(" : "[") +
                                                            format_number(spec.lo) + ", " + format_number(spec.hi) + (spec.open ? ")" : "]"));
                track.values.push_back(v);
            }
        }
        keyframes.tracks.push_back(std::move(track));
    }
    if (keyframes.tracks.empty()) {
        std::string names;
        for (const TrackSpec& spec : specs) names += (names.empty() ? "" : ", ") + spec.name;
        throw InputError(file, path, "keyframes nothing: give at least one of " + names);
    }
    return keyframes;
}

}  // namespace lab::scene
