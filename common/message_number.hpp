// A number as a one-line error message shows it: printf's %g, six significant digits, so that
// "got 100" reads as typed and a float's last bits do not clutter the line.
#pragma once

#include <cstdio>
#include <string>

namespace lab {

inline std::string message_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

}  // namespace lab
