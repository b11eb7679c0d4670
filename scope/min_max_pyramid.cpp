// MinMaxPyramid: per-level min/max blocks, built as complete blocks appear, read from the bottom level up.
#include "min_max_pyramid.h"

#include <algorithm>

namespace scope {

void MinMaxPyramid::append(double value) {
    if (m_count % kLeafSamples == 0)
        m_partial = {value, value};
    else
        widen(m_partial, {value, value});
    ++m_count;
    if (m_count % kLeafSamples == 0) push(0, m_partial);
}

// Block n of level k is complete: store it; when it is the last of 8, blocks n - 7 .. n make block n / 8 of
// level k + 1. Blocks therefore appear in order at every level, and a block exists only once it is complete.
void MinMaxPyramid::push(std::size_t level, ValueRange block) {
    if (level == m_levels.size()) m_levels.emplace_back();
    Level& l = m_levels[level];
    const std::size_t number = l.offset + l.blocks.size();
    l.blocks.push_back(block);
    if ((number + 1) % kFan != 0) return;
    // Siblings may already be gone (dropped samples only): then no query reads the parent.
    for (std::size_t n = std::max(number + 1 - kFan, l.offset); n < number; ++n) widen(block, l.at(n));
    push(level + 1, block); // l is not used after this: emplace_back may move the levels
}

void MinMaxPyramid::dropBefore(std::size_t count) {
    m_dropped = std::max(m_dropped, std::min(count, m_count));
    for (std::size_t k = 0; k < m_levels.size(); ++k) {
        Level& l = m_levels[k];
        const std::size_t gone =
            std::min(m_dropped >> (kLeafShift + kFanShift * k), l.offset + l.blocks.size()) - l.offset;
        // Erase in bulk once half the vector is dead, so a rolling window costs O(1) per sample.
        if (gone == 0 || gone < l.blocks.size() / 2) continue;
        l.blocks.erase(l.blocks.begin(), l.blocks.begin() + std::ptrdiff_t(gone));
        l.offset += gone;
    }
}

// At each level: the blocks before the first whole parent and after the last one (at most 7 each side, side
// by side in memory), then up to the parents; the last level read is a run of at most 14 blocks.
ValueRange MinMaxPyramid::leafRange(std::size_t first, std::size_t last) const {
    ValueRange range = m_levels[0].at(first);
    for (std::size_t k = 0;; ++k) {
        const Level& l = m_levels[k];
        const std::size_t up = (first + kFan - 1) >> kFanShift; // the parents wholly inside [first, last)
        const std::size_t down = last >> kFanShift;
        if (up >= down) {
            for (std::size_t n = first; n < last; ++n) widen(range, l.at(n));
            return range;
        }
        for (std::size_t n = first; n < up << kFanShift; ++n) widen(range, l.at(n));
        for (std::size_t n = down << kFanShift; n < last; ++n) widen(range, l.at(n));
        first = up;
        last = down;
    }
}

} // namespace scope
