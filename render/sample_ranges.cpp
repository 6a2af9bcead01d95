#include "render/sample_ranges.hpp"

#include <algorithm>
#include <cctype>

#include "common/input_error.hpp"

namespace lab::render {

namespace {

// A decimal integer in [0, kMaxEnd] that is the whole of `text`; false otherwise.
bool parse_index(const std::string& text, int64_t* value) {
    if (text.empty() || text.size() > 10) return false;
    int64_t v = 0;
    for (unsigned char c : text) {
        if (!std::isdigit(c)) return false;
        v = v * 10 + (c - '0');
    }
    if (v > SampleRanges::kMaxEnd) return false;
    *value = v;
    return true;
}

}  // namespace

bool parse_index_pair(const std::string& text, int64_t* first, int64_t* end) {
    size_t colon = text.find(':');
    if (colon == std::string::npos) return false;
    return parse_index(text.substr(0, colon), first) && parse_index(text.substr(colon + 1), end) && *first < *end;
}

SampleRanges::SampleRanges(int64_t first, int64_t end) {
    if (first < end) ranges_.push_back({first, end});
}

SampleRanges SampleRanges::parse_range(const std::string& text, const std::string& option) {
    int64_t first = 0, end = 0;
    if (!parse_index_pair(text, &first, &end))
        throw InputError(option, "", "expected A:B, sample indices with 0 <= A < B <= " + std::to_string(kMaxEnd) + ", got \"" + text + "\"");
    return SampleRanges(first, end);
}

SampleRanges SampleRanges::parse(const std::string& text, const std::string& file, const std::string& field) {
    SampleRanges out;
    size_t start = 0;
    while (start < text.size()) {
        size_t comma = text.find(',', start);
        std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        int64_t first = 0, end = 0;
        if (!parse_index_pair(part, &first, &end)) throw InputError(file, field, "\"" + text + "\" is not a list of sample ranges A:B,C:D");
        SampleRanges one(first, end);
        if (out.overlaps(one)) throw InputError(file, field, "\"" + text + "\" has overlapping sample ranges");
        out = out.joined(one);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

std::string SampleRanges::to_string() const {
    std::string text;
    for (const auto& [first, end] : ranges_) {
        if (!text.empty()) text += ',';
        text += std::to_string(first) + ':' + std::to_string(end);
    }
    return text;
}

int64_t SampleRanges::count() const {
    int64_t n = 0;
    for (const auto& [first, end] : ranges_) n += end - first;
    return n;
}

int64_t SampleRanges::end() const { return ranges_.empty() ? 0 : ranges_.back().second; }

bool SampleRanges::overlaps(const SampleRanges& other) const {
    for (const auto& [a0, a1] : ranges_)
        for (const auto& [b0, b1] : other.ranges_)
            if (a0 < b1 && b0 < a1) return true;
    return false;
}

void SampleRanges::add(int64_t first, int64_t end) {
    if (first >= end) return;
    ranges_.push_back({first, end});
    std::sort(ranges_.begin(), ranges_.end());
    std::vector<std::pair<int64_t, int64_t>> merged;
    for (const auto& r : ranges_) {
        if (!merged.empty() && r.first <= merged.back().second)
            merged.back().second = std::max(merged.back().second, r.second);
        else
            merged.push_back(r);
    }
    ranges_ = std::move(merged);
}

SampleRanges SampleRanges::joined(const SampleRanges& other) const {
    SampleRanges out = *this;
    for (const auto& [first, end] : other.ranges_) out.add(first, end);
    return out;
}

}  // namespace lab::render
