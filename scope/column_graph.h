// ColumnGraph: the QCPGraph ScopePlot draws its traces with; a dense (min/max decimated) trace is filled
// pixel column by pixel column instead of stroked as a polyline. GUI thread only.
#pragma once

#include "column_cache.h"

#include <qcustomplot.h>

#include <vector>

namespace scope {

// Each pixel column is filled from the lowest to the highest point in it: the pixels a 1 px polyline through
// the min/max zigzag would set, filled several times faster than the raster engine strokes them. Where
// neighbouring columns share rows, the shared band is one rectangle (filled row by row, as memory lies) and
// only the columns' ragged ends are filled a column at a time. Sparse traces, and vector exports (PDF), are
// drawn as QCPGraph draws them.
class ColumnGraph final : public QCPGraph {
public:
    using QCPGraph::QCPGraph; // registers with the plot, as QCustomPlot::addGraph does

    // The frame's data: channel `channel` of `store` over [from_s, to_s] on `pixels` columns, decimated by
    // this graph's ColumnCache (a pan or a zoom back reuses what earlier frames computed).
    void showRange(const SeriesStore& store, std::size_t channel, double from_s, double to_s, int pixels);
    // Whether the data are per-column min/max pairs, drawn as filled columns, or the samples themselves.
    bool isDense() const { return m_dense; }

protected:
    void draw(QCPPainter* painter) override;

private:
    struct PixelColumn {
        int x;
        int top; // pixel rows, top <= bottom
        int bottom;
    };
    // m_columns as rectangles, in m_rects.
    void band();

    ColumnCache m_cache;
    std::vector<Sample> m_points; // the cache's answer, before it becomes QCPGraphData
    bool m_dense = false;
    std::vector<PixelColumn> m_columns; // the frame's columns, left to right (kept to reuse the memory)
    QVector<QRect> m_rects;             // the rectangles that fill the columns
};

} // namespace scope
