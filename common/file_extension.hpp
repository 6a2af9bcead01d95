// A path's extension as the lab compares it: lower-case, with its dot (".exr"), so that a file
// named SKY.EXR is read and written as what it is.
#pragma once

#include <cctype>
#include <filesystem>
#include <string>

namespace lab {

inline std::string lowercase_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return ext;
}

}  // namespace lab
