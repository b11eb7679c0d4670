// MinMaxPyramid: the min and max of a channel's values per block of 16, 128, 1024, ... samples (a level per
// power of 8), kept as samples are appended and dropped, so that the min and max of any run of samples
// costs O(log n) block reads instead of a scan. SeriesStore keeps one per channel for its decimation.
#pragma once

#include <cstddef>
#include <vector>

namespace scope {

struct ValueRange {
    double minimum = 0;
    double maximum = 0;
};

// Widens `range` to take in `by`. NaN is a gap, not an extreme: it never replaces a number, and a range
// stays NaN only while everything in it is NaN (std::min would keep a leading NaN for good).
inline void widen(ValueRange& range, const ValueRange& by) {
    if (by.minimum < range.minimum || range.minimum != range.minimum) range.minimum = by.minimum;
    if (by.maximum > range.maximum || range.maximum != range.maximum) range.maximum = by.maximum;
}

class MinMaxPyramid {
public:
    // Level 0 holds one block per kLeafSamples samples; the raw samples of a partial block are read by the
    // caller. 16 keeps the pyramid under 1/12 of the samples' size (two doubles per 16 time-value pairs).
    static constexpr std::size_t kLeafShift = 4;
    static constexpr std::size_t kLeafSamples = std::size_t(1) << kLeafShift;
    // Each block above level 0 spans 8 of the level below: a query reads at most 7 blocks a side a level,
    // side by side in memory, from a third as many levels as halving would give (a decimation is bound by
    // cache misses, about one a level, more than by the blocks it reads).
    static constexpr std::size_t kFanShift = 3;
    static constexpr std::size_t kFan = std::size_t(1) << kFanShift;

    // Sample indices are absolute: the first sample ever appended is 0, and dropping keeps the numbering.
    void append(double value);
    // Forgets samples [0, count): the blocks holding only those go; a block they share with kept samples
    // stays but is never read again (a query only reads blocks wholly inside its range).
    void dropBefore(std::size_t count);
    void clear() { *this = MinMaxPyramid(); }

    std::size_t size() const { return m_count; }      // samples appended so far (the next absolute index)
    std::size_t dropped() const { return m_dropped; } // absolute index of the first sample kept
    // Whole leaf blocks [first, last) (leaf i holds samples [16 i, 16 i + 16)), every one complete and
    // kept: first < last <= size() / 16.
    ValueRange leafRange(std::size_t first, std::size_t last) const;

private:
    // Blocks of 16 * 8^k samples; blocks[i] is block number (offset + i).
    struct Level {
        std::size_t offset = 0;
        std::vector<ValueRange> blocks;
        const ValueRange& at(std::size_t block) const { return blocks[block - offset]; }
    };
    // A complete block at level k: stored; the last of 8 siblings also makes, with them, one of level k + 1.
    void push(std::size_t level, ValueRange block);

    std::vector<Level> m_levels;
    ValueRange m_partial; // the samples of the leaf block still filling (m_count % 16 of them)
    std::size_t m_count = 0;
    std::size_t m_dropped = 0;
};

} // namespace scope
