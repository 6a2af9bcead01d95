// What an image file says about how it was made (scene, samples, time, tone map...): key-value
// pairs stored in the file's header, so a result can be traced back without a side file.
#pragma once

#include <map>
#include <string>
#include <variant>

namespace lab::film {

using MetadataValue = std::variant<std::string, int, float>;

struct ImageMetadata {
    // Keys are short names ("scene", "spp", "seconds"): letters, digits, '_', '-', '.'. In the file
    // each becomes the attribute "dtoadq:<key>". EXR keeps the type; PNG text chunks hold text
    // only, so numbers come back from a PNG as strings (ints exactly, floats with 9 digits).
    std::map<std::string, MetadataValue> values;
    // The file's "Software" attribute.
    std::string software = "dtoadq";

    void set(const std::string& key, const std::string& value) { values[key] = value; }
    void set(const std::string& key, const char* value) { values[key] = std::string(value); }
    void set(const std::string& key, int value) { values[key] = value; }
    void set(const std::string& key, float value) { values[key] = value; }
    void set(const std::string& key, double value) { values[key] = float(value); }

    // nullptr when the key is absent.
    const MetadataValue* find(const std::string& key) const {
        auto it = values.find(key);
        return it == values.end() ? nullptr : &it->second;
    }
};

// The value as text: strings as they are, ints in decimal, floats with 9 significant digits
// (enough to read the same float back).
std::string metadata_text(const MetadataValue& value);

}  // namespace lab::film
