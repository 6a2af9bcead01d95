// What the chart tests read back: whether a file is a PNG of some size, and a CSV's lines.
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

// A PNG (its signature) of more than `bytes` bytes: a chart with something drawn on it.
inline bool is_png_larger_than(const std::filesystem::path& file, std::uintmax_t bytes) {
    std::ifstream in(file, std::ios::binary);
    char magic[8] = {};
    in.read(magic, 8);
    return std::string(magic, 8) == "\x89PNG\r\n\x1a\n" && std::filesystem::file_size(file) > bytes;
}

inline std::vector<std::string> lines_of(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}
