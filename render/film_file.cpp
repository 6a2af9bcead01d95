#include "render/film_file.hpp"

#include <cmath>
#include <map>
#include <set>

#include "common/input_error.hpp"

namespace lab::render {

namespace {

const std::vector<std::string>& channel_names() {
    static const std::vector<std::string> names = {"film.sum.R",     "film.sum.G",     "film.sum.B",    "film.nonfinite",
                                                   "film.splat.R",   "film.splat.G",   "film.splat.B",  "film.squares.R",
                                                   "film.squares.G", "film.squares.B"};
    return names;
}

const char* const kPassesChannel = "film.squares.passes";

// Metadata that differs between parts of one render and does not change what it estimates (the
// display's tone map, exposure and denoising change the image shown, never the film; a sequence's
// frame number and rate say where a render sits in it, and its scene_time, compared, what it shows).
bool is_per_part(const std::string& key) {
    static const std::set<std::string> keys = {"spp",      "sample_ranges", "seconds",  "device", "nonfinite_samples", "lost_rays",
                                               "tonemap",  "exposure",      "merged_parts", "denoise", "frame", "fps"};
    return keys.count(key) > 0;
}

// Keys that films written before the setting existed lack, and the value such a film rendered at:
// a film from before scene time shows the scene at time 0, and resumes and merges as one.
const std::map<std::string, std::string>& implied_when_absent() {
    static const std::map<std::string, std::string> implied = {{"scene_time", "0"}};
    return implied;
}

std::string text_of(const film::ImageMetadata& m, const std::string& key) {
    const film::MetadataValue* v = m.find(key);
    if (v) return film::metadata_text(*v);
    const auto implied = implied_when_absent().find(key);
    return implied != implied_when_absent().end() ? implied->second : std::string("(absent)");
}

// A count stored as text ("nonfinite_samples", "lost_rays"); 0 when absent or not a number.
unsigned long long count_of(const film::ImageMetadata& m, const std::string& key) {
    const film::MetadataValue* v = m.find(key);
    if (!v) return 0;
    try {
        return std::stoull(film::metadata_text(*v));
    } catch (const std::exception&) {
        return 0;
    }
}

}  // namespace

std::vector<film::ImageChannel> film_channels(const FilmReadback& film) {
    const std::vector<std::string>& names = channel_names();
    size_t pixels = film.accumulation.size() / 4;
    std::vector<film::ImageChannel> channels;
    for (size_t c = 0; c < names.size(); ++c) {
        film::ImageChannel channel{names[c], std::vector<float>(pixels)};
        for (size_t p = 0; p < pixels; ++p)
            channel.values[p] = c < 4 ? film.accumulation[4 * p + c] : c < 7 ? film.splat[3 * p + (c - 4)] : film.squares[4 * p + (c - 7)];
        channels.push_back(std::move(channel));
    }
    // A film squared per pass (render::add_pass_squares) keeps its count of passes; one squared per
    // sample has none (0 everywhere) and no such channel.
    film::ImageChannel passes{kPassesChannel, std::vector<float>(pixels)};
    bool per_pass = false;
    for (size_t p = 0; p < pixels; ++p) {
        passes.values[p] = film.squares[4 * p + 3];
        per_pass = per_pass || passes.values[p] != 0.0f;
    }
    if (per_pass) channels.push_back(std::move(passes));
    return channels;
}

FilmFile read_film_file(const std::string& path) {
    FilmFile file;
    file.path = path;
    film::read_image(path, &file.metadata);  // the format and the colour channels, checked as every image
    std::vector<film::ImageChannel> channels;
    try {
        channels = film::read_exr_channels(path, channel_names(), &file.width, &file.height);
    } catch (const InputError& e) {
        throw InputError(path, "", std::string("has no film to merge or resume (") + e.what() +
                                       "): only an EXR written by dtoadq render or preview holds one");
    }
    size_t pixels = size_t(file.width) * size_t(file.height);
    std::vector<film::ImageChannel> passes;  // absent from a film squared per sample
    try {
        int width = 0, height = 0;
        passes = film::read_exr_channels(path, {kPassesChannel}, &width, &height);
    } catch (const InputError&) {
    }
    file.film.accumulation.resize(4 * pixels);
    file.film.splat.resize(3 * pixels);
    file.film.squares.assign(4 * pixels, 0.0f);
    for (size_t p = 0; p < pixels; ++p) {
        for (size_t c = 0; c < 4; ++c) file.film.accumulation[4 * p + c] = channels[c].values[p];
        for (size_t c = 0; c < 3; ++c) file.film.splat[3 * p + c] = channels[4 + c].values[p];
        for (size_t c = 0; c < 3; ++c) file.film.squares[4 * p + c] = channels[7 + c].values[p];
        if (!passes.empty()) file.film.squares[4 * p + 3] = passes[0].values[p];
        float nonfinite = file.film.accumulation[4 * p + 3];
        if (!(nonfinite >= 0.0f && nonfinite == std::floor(nonfinite)))
            throw InputError(path, "film.nonfinite", "pixel " + std::to_string(p) + " holds " + std::to_string(nonfinite) + ", not a count");
    }
    const film::MetadataValue* ranges = file.metadata.find("sample_ranges");
    if (!ranges) throw InputError(path, "dtoadq:sample_ranges", "missing: the file does not say which samples it holds");
    file.ranges = SampleRanges::parse(film::metadata_text(*ranges), path, "dtoadq:sample_ranges");
    if (file.ranges.empty()) throw InputError(path, "dtoadq:sample_ranges", "holds no samples");
    return file;
}

void check_same_render(const std::string& reference_name, const film::ImageMetadata& reference, int width, int height, const FilmFile& part) {
    if (part.width != width || part.height != height)
        throw InputError(part.path, "size",
                         std::to_string(part.width) + "x" + std::to_string(part.height) + ", but " + reference_name + " is " +
                             std::to_string(width) + "x" + std::to_string(height));
    std::set<std::string> keys;
    for (const auto& [key, value] : reference.values) keys.insert(key);
    for (const auto& [key, value] : part.metadata.values) keys.insert(key);
    for (const std::string& key : keys) {
        if (is_per_part(key)) continue;
        std::string mine = text_of(part.metadata, key), theirs = text_of(reference, key);
        if (mine != theirs)
            throw InputError(part.path, "dtoadq:" + key, "\"" + mine + "\", but " + reference_name + " has \"" + theirs + "\": not a part of the same render");
    }
}

FilmFile merge_film_files(const std::vector<FilmFile>& parts) {
    if (parts.empty()) throw std::invalid_argument("merge_film_files: no parts");
    FilmFile merged = parts.front();
    float seconds = 0.0f;
    unsigned long long nonfinite = 0, lost = 0;
    int merged_parts = 0;
    std::set<std::string> devices;
    for (size_t k = 0; k < parts.size(); ++k) {
        const FilmFile& part = parts[k];
        if (k > 0) {
            check_same_render(parts.front().path, parts.front().metadata, merged.width, merged.height, part);
            if (merged.ranges.overlaps(part.ranges))
                throw InputError(part.path, "dtoadq:sample_ranges",
                                 part.ranges.to_string() + " overlaps the samples of the parts before it (" + merged.ranges.to_string() +
                                     "): a sample would count twice");
            merged.ranges = merged.ranges.joined(part.ranges);
            for (size_t i = 0; i < merged.film.accumulation.size(); ++i) merged.film.accumulation[i] += part.film.accumulation[i];
            for (size_t i = 0; i < merged.film.splat.size(); ++i) merged.film.splat[i] += part.film.splat[i];
            for (size_t i = 0; i < merged.film.squares.size(); ++i) merged.film.squares[i] += part.film.squares[i];
        }
        if (const film::MetadataValue* s = part.metadata.find("seconds"); s && std::holds_alternative<float>(*s)) seconds += std::get<float>(*s);
        nonfinite += count_of(part.metadata, "nonfinite_samples");
        lost += count_of(part.metadata, "lost_rays");
        const film::MetadataValue* n = part.metadata.find("merged_parts");
        merged_parts += n && std::holds_alternative<int>(*n) ? std::get<int>(*n) : 1;
        devices.insert(text_of(part.metadata, "device"));
    }
    merged.path = "merged";
    merged.metadata.set("spp", int(merged.ranges.count()));
    merged.metadata.set("sample_ranges", merged.ranges.to_string());
    merged.metadata.set("seconds", seconds);
    merged.metadata.set("nonfinite_samples", std::to_string(nonfinite));
    merged.metadata.set("lost_rays", std::to_string(lost));
    std::string device;
    for (const std::string& d : devices) device += (device.empty() ? "" : "; ") + d;
    merged.metadata.set("device", device);
    merged.metadata.set("merged_parts", merged_parts);
    merged.metadata.set("denoise", "off");  // the merge resolves its image from the film, as rendered
    return merged;
}

}  // namespace lab::render
