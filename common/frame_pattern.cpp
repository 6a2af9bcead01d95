#include "common/frame_pattern.hpp"

#include <cctype>
#include <stdexcept>

#include "common/input_error.hpp"

namespace lab {

namespace {

// The pattern's pieces: the text before the conversion, its zero-padded width (0 for %d), the text
// after; and how many conversions there are (-1: a % that starts none of %d, %0Nd, %%).
struct Parsed {
    std::string before, after;
    int width = 0;
    int conversions = 0;
};

Parsed parse(const std::string& pattern) {
    Parsed p;
    std::string* text = &p.before;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            *text += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            *text += '%';
            ++i;
            continue;
        }
        size_t j = i + 1;
        int width = 0;
        if (j < pattern.size() && pattern[j] == '0') {
            ++j;
            while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width < 100) width = width * 10 + (pattern[j++] - '0');
        }
        if (j >= pattern.size() || pattern[j] != 'd') {
            p.conversions = -1;
            return p;
        }
        ++p.conversions;
        p.width = width;
        text = &p.after;
        i = j;
    }
    return p;
}

}  // namespace

bool is_frame_pattern(const std::string& pattern) { return parse(pattern).conversions == 1; }

void check_frame_pattern(const std::string& pattern, const std::string& what) {
    const int n = parse(pattern).conversions;
    if (n == 1) return;
    const std::string has = n < 0 ? "a % that is not %d, %0Nd or %%" : n == 0 ? "no %d" : std::to_string(n) + " of them";
    throw InputError(pattern, "", what + " needs one %d or %0Nd for the frame number (frame_%04d.exr), and this has " + has);
}

std::string frame_path(const std::string& pattern, long long frame) {
    const Parsed p = parse(pattern);
    if (p.conversions != 1 || frame < 0) throw std::invalid_argument("frame_path: not a frame pattern, or a negative frame");
    std::string digits = std::to_string(frame);
    if (int(digits.size()) < p.width) digits.insert(0, size_t(p.width) - digits.size(), '0');
    return p.before + digits + p.after;
}

}  // namespace lab
