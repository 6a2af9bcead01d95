#include "common/image_claim.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "common/input_error.hpp"

namespace lab::codec {

namespace {

uint64_t ceil_div(uint64_t a, uint64_t b) { return (a + b - 1) / b; }

std::string bytes_text(uint64_t bytes) {
    char text[32];
    if (bytes >= 1000000000u) std::snprintf(text, sizeof text, "%.1f GB", double(bytes) / 1e9);
    else std::snprintf(text, sizeof text, "%.0f MB", double(bytes) / 1e6);
    return text;
}

}  // namespace

uint64_t minimum_encoded_bytes(const std::string& format, int width, int height, int channels) {
    if (width <= 0 || height <= 0 || channels <= 0) return 0;
    const uint64_t w = uint64_t(width), h = uint64_t(height);
    if (format == "hdr") {
        const bool run_length = width >= 8 && width <= 32767;
        return h * (run_length ? 4 + 4 * 2 * ceil_div(w, 127) : 4 * w);
    }
    if (format == "openexr") return ceil_div(ceil_div(w, 8) * ceil_div(h, 8) * uint64_t(channels) * 2, 1032);
    if (format == "png") return ceil_div(h * (1 + w * uint64_t(channels)), 1032);
    return 0;
}

uint64_t physical_memory_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : 0;
}

void check_image_claim(const std::string& path, const Header& header, uint64_t file_bytes, int floats_per_pixel, uint64_t memory_bytes) {
    const std::string size = std::to_string(header.width) + " x " + std::to_string(header.height);
    if (header.width <= 0 || header.height <= 0) throw InputError(path, "size", size + " holds no pixel");
    const uint64_t least = minimum_encoded_bytes(header.format, header.width, header.height, header.channels);
    if (file_bytes < least)
        throw InputError(path, "size",
                         size + " cannot be held by a file of " + std::to_string(file_bytes) + " bytes (at least " +
                             std::to_string(least) + " in " + header.format + "): a corrupt header");
    const uint64_t needed = uint64_t(header.width) * uint64_t(header.height) * uint64_t(floats_per_pixel) * sizeof(float);
    if (memory_bytes > 0 && needed > memory_bytes / 2)
        throw InputError(path, "size",
                         size + " needs " + bytes_text(needed) + " to read, more than half of this machine's " + bytes_text(memory_bytes));
}

void check_image_file_claim(const std::string& path, const Header& header, int floats_per_pixel) {
    std::error_code error;
    const uintmax_t file_bytes = std::filesystem::file_size(path, error);
    check_image_claim(path, header, error ? 0 : uint64_t(file_bytes), floats_per_pixel, physical_memory_bytes());
}

}  // namespace lab::codec
