// Reading a whole input file (a preset, a scene) with a size limit of its own: a file far larger
// than any real one of its kind is refused with one line before it fills memory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/input_error.hpp"

namespace lab {

// Throws InputError(path, "", "cannot open <kind> file") when it cannot be read, and
// InputError(path, "", "is N bytes, more than the M a <kind> file may hold") beyond max_bytes.
inline std::string read_text_file(const std::string& path, std::uintmax_t max_bytes, const std::string& kind) {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    if (!in || std::filesystem::is_directory(path, ec)) throw InputError(path, "", "cannot open " + kind + " file");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_bytes)
        throw InputError(path, "", "is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) + " a " + kind +
                                       " file may hold");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace lab
