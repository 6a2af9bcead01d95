// Which sample indices a film holds. The random numbers of sample i of pixel p are keyed by (p, i)
// alone (kernels/rng.h), so renders of disjoint index ranges are independent parts of one render:
// they can run on different machines and be merged (dtoadq merge), and a render can be continued
// from where it stopped (--resume) with the indices that follow.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace lab::render {

// Half-open ranges [first, end) of sample indices, sorted, disjoint and not touching (adjacent
// ranges are joined), so equal sets of indices have equal text.
class SampleRanges {
public:
    SampleRanges() = default;
    // One range; empty when first >= end.
    SampleRanges(int64_t first, int64_t end);

    // "A:B" (one range, A < B) as the command line takes it; throws lab::InputError(option, "", ...).
    static SampleRanges parse_range(const std::string& text, const std::string& option);
    // The text form of to_string ("0:64,128:192"; "" for none); throws lab::InputError(file, field, ...).
    static SampleRanges parse(const std::string& text, const std::string& file, const std::string& field);
    std::string to_string() const;

    bool empty() const { return ranges_.empty(); }
    int64_t count() const;                        // how many indices
    int64_t end() const;                          // one past the largest index; 0 when empty
    bool overlaps(const SampleRanges& other) const;
    // The union; the caller checks overlaps() first where an overlap is an error.
    SampleRanges joined(const SampleRanges& other) const;
    const std::vector<std::pair<int64_t, int64_t>>& ranges() const { return ranges_; }
    bool operator==(const SampleRanges& other) const { return ranges_ == other.ranges_; }

    // The largest sample index a render may use: the kernels key their random numbers by a 32-bit
    // sample index (kernels/render_settings.h holds it as an int).
    static constexpr int64_t kMaxEnd = (int64_t(1) << 31) - 1;

private:
    std::vector<std::pair<int64_t, int64_t>> ranges_;
    void add(int64_t first, int64_t end);
};

// "A:B", decimal integers with 0 <= A < B <= SampleRanges::kMaxEnd (sample indices, frame
// numbers), into first and end; false for anything else.
bool parse_index_pair(const std::string& text, int64_t* first, int64_t* end);

}  // namespace lab::render
