#include "film/image_metadata.hpp"

#include <cstdio>

namespace lab::film {

std::string metadata_text(const MetadataValue& value) {
    if (const std::string* s = std::get_if<std::string>(&value)) return *s;
    if (const int* i = std::get_if<int>(&value)) return std::to_string(*i);
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(std::get<float>(value)));
    return text;
}

}  // namespace lab::film
