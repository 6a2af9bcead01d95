#include "report/reference_cache.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "film/image_output.hpp"

namespace lab::report {

namespace {

// A metadata value as a number, or -1 when it is absent or not a number.
double metadata_number(const film::ImageMetadata& m, const std::string& key) {
    const film::MetadataValue* v = m.find(key);
    if (v == nullptr) return -1.0;
    if (const float* f = std::get_if<float>(v)) return *f;
    if (const int* i = std::get_if<int>(v)) return *i;
    return -1.0;
}

}  // namespace

Reference cached_reference(const std::string& exr, const std::string& key, const RendererFactory& make, const render::RenderInput& input,
                           double seconds, bool* reused) {
    *reused = false;
    std::error_code ec;
    if (std::filesystem::is_regular_file(exr, ec)) {
        try {
            film::ImageMetadata m;
            Reference r;
            r.image = film::read_image(exr, &m);
            const film::MetadataValue* stored = m.find("reference_key");
            const bool same_key = stored != nullptr && film::metadata_text(*stored) == key;
            r.noise = metadata_number(m, "reference_noise");
            r.relative_noise = metadata_number(m, "reference_relative_noise");
            r.samples_per_pixel = int(metadata_number(m, "spp"));
            if (same_key && r.image.width == input.settings.width && r.image.height == input.settings.height && r.noise >= 0.0 &&
                r.relative_noise >= 0.0 && r.samples_per_pixel > 0) {
                *reused = true;
                return r;
            }
        } catch (const std::exception&) {
            // an unreadable or foreign file: rendered again and replaced below
        }
    }
    Reference r = render_reference(make, input, seconds);
    film::ImageMetadata m;
    m.set("reference_key", key);
    m.set("reference_noise", r.noise);
    m.set("reference_relative_noise", r.relative_noise);
    m.set("spp", r.samples_per_pixel);
    m.set("seconds", seconds);
    std::filesystem::create_directories(std::filesystem::path(exr).parent_path(), ec);
    film::write_exr(exr, r.image, m);
    return r;
}

std::string text_digest(const std::string& text) {
    uint64_t h = 14695981039346656037ull;  // FNV-1a offset basis
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

}  // namespace lab::report
