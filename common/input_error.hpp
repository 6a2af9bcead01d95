// Bad input from a user (a preset, a scene, an image, a parameter): one line naming the file and
// the field. The command line prints it and exits non-zero; nothing already written is touched.
#pragma once

#include <stdexcept>
#include <string>

namespace lab {

class InputError : public std::runtime_error {
public:
    // "FILE: FIELD: problem", or "FILE: problem" when no field applies.
    InputError(const std::string& file, const std::string& field, const std::string& problem)
        : std::runtime_error(file + (field.empty() ? "" : ": " + field) + ": " + problem) {}
};

}  // namespace lab
