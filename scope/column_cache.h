// ColumnCache: one plotted channel's min/max columns, kept per zoom level so that a pan computes only the
// columns it uncovers and a zoom back to a level seen before computes none. Widget-free; GUI thread only.
#pragma once

#include "series_store.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace scope {

class ColumnCache {
public:
    static constexpr std::size_t kLevels = 8; // zoom levels kept, the most recently used

    // What SeriesStore::decimate gives (and, when the range holds at most two samples a pixel, exactly
    // that), except that min/max columns lie on the zoom level's grid (SeriesStore::gridColumns): anchored at
    // t = 0, levelWidth() wide, so one to two of them a pixel; each holds its true min and max, so a pixel
    // column shows its own to within a pixel. Returns true when the points are min/max pairs.
    bool points(const SeriesStore& store, std::size_t channel, double from_s, double to_s, std::size_t pixels,
                std::vector<Sample>& out);

    // The grid of a view showing span_s on `pixels` columns: the widest 2^(k/4) s that is not wider than a
    // pixel (levels a quarter octave apart, so a zoom settles on one and the grid stays put while panning).
    static double levelWidth(double span_s, std::size_t pixels);

private:
    struct GridColumn {
        std::size_t first; // its samples [first, last) (indices of the store revision the cache holds)
        std::size_t last;
        Sample points[2];  // as SeriesStore::columnPoints draws it
        std::size_t count; // points used
    };
    struct Level {
        double width_s = 0;
        std::int64_t first = 0; // grid index of columns.front()
        std::deque<GridColumn> columns;
        std::uint64_t used = 0; // when it was last used, for eviction
    };
    Level& level(double width_s);
    // Makes `level` hold grid columns [first, last), computing those it lacks; keeps it O(last - first).
    void cover(const SeriesStore& store, Level& level, std::int64_t first, std::int64_t last);

    std::size_t m_channel = 0;
    std::uint64_t m_revision = 0; // of the store the levels were computed from (unique across stores)
    std::vector<Level> m_levels;
    std::uint64_t m_clock = 0;
    std::vector<Column> m_columns;   // scratch for SeriesStore::gridColumns
    std::vector<GridColumn> m_fresh; // scratch: the columns a cover() computes
};

} // namespace scope
