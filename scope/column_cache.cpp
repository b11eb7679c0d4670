// ColumnCache: grid columns per zoom level, extended as the view pans, evicted least recently used.
#include "column_cache.h"

#include <algorithm>
#include <cmath>

namespace scope {

double ColumnCache::levelWidth(double span_s, std::size_t pixels) {
    const double pixel = span_s / double(pixels);
    if (!(pixel > 0) || !std::isfinite(pixel)) return 0;
    const double k = std::floor(4 * std::log2(pixel));
    const double width = std::exp2(k / 4);
    return width <= pixel ? width : std::exp2((k - 1) / 4); // log2 and exp2 may round past the pixel
}

ColumnCache::Level& ColumnCache::level(double width_s) {
    ++m_clock;
    for (Level& l : m_levels)
        if (l.width_s == width_s) {
            l.used = m_clock;
            return l;
        }
    if (m_levels.size() == kLevels) {
        Level& oldest = *std::min_element(m_levels.begin(), m_levels.end(),
                                          [](const Level& a, const Level& b) { return a.used < b.used; });
        oldest = Level{width_s, 0, {}, m_clock};
        return oldest;
    }
    m_levels.push_back(Level{width_s, 0, {}, m_clock});
    return m_levels.back();
}

void ColumnCache::cover(const SeriesStore& store, Level& l, std::int64_t first, std::int64_t last) {
    const auto compute = [&](std::int64_t from, std::int64_t to) {
        m_columns.assign(std::size_t(to - from), Column{});
        store.gridColumns(m_channel, l.width_s, from, m_columns);
        m_fresh.clear();
        for (const Column& c : m_columns) {
            GridColumn g{c.first, c.last, {}, 0};
            g.count = store.columnPoints(m_channel, c, g.points);
            m_fresh.push_back(g);
        }
    };
    const std::int64_t end = l.first + std::int64_t(l.columns.size());
    if (l.columns.empty() || last <= l.first || first >= end) { // nothing to keep: a jump, or a new level
        compute(first, last);
        l.columns.assign(m_fresh.begin(), m_fresh.end());
        l.first = first;
    } else {
        if (first < l.first) {
            compute(first, l.first);
            l.columns.insert(l.columns.begin(), m_fresh.begin(), m_fresh.end());
            l.first = first;
        }
        if (last > end) {
            compute(end, last);
            l.columns.insert(l.columns.end(), m_fresh.begin(), m_fresh.end());
        }
    }
    // What a pan back could use, not the whole record: at most half a view's width either side.
    const std::int64_t margin = (last - first) / 2 + 1;
    while (l.first < first - margin) {
        l.columns.pop_front();
        ++l.first;
    }
    while (l.first + std::int64_t(l.columns.size()) > last + margin) l.columns.pop_back();
}

bool ColumnCache::points(const SeriesStore& store, std::size_t channel, double from_s, double to_s, std::size_t pixels,
                         std::vector<Sample>& out) {
    out.clear();
    const auto& s = store.channel(channel).samples;
    if (pixels == 0 || s.empty() || !(from_s <= to_s)) return false;
    const auto [first, last] = store.indexRange(channel, from_s, to_s);
    const double width = levelWidth(to_s - from_s, pixels);
    if (last - first <= 2 * pixels || width == 0) return store.decimate(channel, from_s, to_s, pixels, out);
    if (channel != m_channel || store.revision() != m_revision) { // other samples: nothing kept is theirs
        m_levels.clear();
        m_channel = channel;
        m_revision = store.revision();
    }
    Level& l = level(width);
    const auto g0 = std::int64_t(std::floor(from_s / width)); // the grid columns that hold [from_s, to_s]
    const auto g1 = std::int64_t(std::floor(to_s / width)) + 1;
    cover(store, l, g0, g1);
    const auto columns = l.columns.begin() + std::ptrdiff_t(g0 - l.first);
    const auto columnsEnd = columns + std::ptrdiff_t(g1 - g0);
    const auto full = std::find_if(columns, columnsEnd, [](const GridColumn& g) { return g.count > 0; });
    if (full == columnsEnd) return true; // no samples in view (cannot be: there are over 2 a pixel)
    // The sample before the first column's and after the last's, so the line runs to the plot's edges.
    if (full->first > 0) out.push_back(s[full->first - 1]);
    std::size_t end = 0;
    for (auto it = full; it != columnsEnd; ++it) {
        out.insert(out.end(), it->points, it->points + it->count);
        if (it->count > 0) end = it->last;
    }
    if (end < s.size()) out.push_back(s[end]);
    return true;
}

} // namespace scope
