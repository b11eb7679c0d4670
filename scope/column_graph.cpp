// ColumnGraph: dense traces as filled pixel columns, joined where the line crosses from one to the next.
#include "column_graph.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace scope {

namespace {

// Segment a-b (a left of b) cut to x in [left, right]; false when none of it is there. The points just
// outside the visible range can be millions of pixels away when zoomed in: Qt is not handed those.
bool clipToColumns(QPointF& a, QPointF& b, double left, double right) {
    if (b.x() < left || a.x() > right) return false;
    const QPointF a0 = a;
    const QPointF b0 = b;
    const auto at = [&a0, &b0](double x) {
        return QPointF(x, a0.y() + (b0.y() - a0.y()) * (x - a0.x()) / (b0.x() - a0.x()));
    };
    if (a0.x() < left) a = at(left);
    if (b0.x() > right) b = at(right);
    return true;
}

constexpr int kMinBand = 4; // rows: a narrower shared band is not worth a rectangle of its own

} // namespace

// Greedy bands: a run of adjacent columns keeps the rows all of them share while that is at least kMinBand
// rows and what the next column adds to the band outweighs what the band loses: its rows shrink by the same
// amount in every column so far, and those rows are then filled column by column (about ten times slower a
// pixel than along a row). The band is one rectangle; each column's rows above and below it are one each.
// A solid block of signal is then a handful of rectangles.
void ColumnGraph::band() {
    m_rects.clear();
    const std::size_t n = m_columns.size();
    for (std::size_t i = 0; i < n;) {
        int top = m_columns[i].top;
        int bottom = m_columns[i].bottom;
        std::size_t j = i + 1;
        for (; j < n && m_columns[j].x == m_columns[j - 1].x + 1; ++j) {
            const int t = std::max(top, m_columns[j].top);
            const int b = std::min(bottom, m_columns[j].bottom);
            const int shared = b - t + 1;
            if (shared < kMinBand || std::size_t((bottom - top + 1) - shared) * (j - i) > std::size_t(shared)) break;
            top = t;
            bottom = b;
        }
        m_rects.append(QRect(m_columns[i].x, top, m_columns[j - 1].x - m_columns[i].x + 1, bottom - top + 1));
        for (std::size_t k = i; k < j && j - i > 1; ++k) {
            const PixelColumn& c = m_columns[k];
            if (c.top < top) m_rects.append(QRect(c.x, c.top, 1, top - c.top));
            if (c.bottom > bottom) m_rects.append(QRect(c.x, bottom + 1, 1, c.bottom - bottom));
        }
        i = j;
    }
}

void ColumnGraph::showRange(const SeriesStore& store, std::size_t channel, double from_s, double to_s, int pixels) {
    m_dense = m_cache.points(store, channel, from_s, to_s, std::size_t(std::max(pixels, 1)), m_points);
    QVector<QCPGraphData> data(qsizetype(m_points.size()));
    for (std::size_t i = 0; i < m_points.size(); ++i) data[qsizetype(i)] = {m_points[i].time_s, m_points[i].value};
    mDataContainer->set(data, true); // time-ordered, as the cache promises
}

void ColumnGraph::draw(QCPPainter* painter) {
    QCPAxis* keyAxis = mKeyAxis.data();
    QCPAxis* valueAxis = mValueAxis.data();
    if (!m_dense || painter->modes().testFlag(QCPPainter::pmVectorized) || !keyAxis || !valueAxis ||
        keyAxis->orientation() != Qt::Horizontal || keyAxis->rangeReversed() || mLineStyle != lsLine) {
        QCPGraph::draw(painter);
        return;
    }
    const QRect area = clipRect();
    const double left = area.left() - 1.0;
    const double right = area.right() + 1.0;
    const double top = area.top() - 1.0;       // rows beyond the area are clipped anyway; clamping (before
    const double bottom = area.bottom() + 1.0; // the conversion) keeps a far-off value from overflowing int
    const QColor colour = mPen.color();
    const int thickness = std::max(1, qRound(mPen.widthF())); // a wide pen thickens flat stretches as a line
    painter->setPen(mPen);                                    // for lines across empty columns

    int column = INT_MIN; // the pixel column being gathered (INT_MIN: none)
    double high = 0;      // its topmost and bottommost pixel row (rows grow downwards)
    double low = 0;
    m_columns.clear();
    const auto flush = [&] {
        if (column == INT_MIN) return;
        m_columns.push_back({column, int(std::clamp(std::floor(high) - (thickness - 1) / 2, top, bottom)),
                             int(std::clamp(std::floor(low) + thickness / 2, top, bottom))});
        column = INT_MIN;
    };
    const auto inside = [left, right](const QPointF& p) { return p.x() >= left && p.x() <= right; };
    QPointF last;
    bool haveLast = false;
    for (auto it = mDataContainer->constBegin(); it != mDataContainer->constEnd(); ++it) {
        const QPointF p(keyAxis->coordToPixel(it->key), valueAxis->coordToPixel(it->value));
        if (!std::isfinite(p.x()) || !std::isfinite(p.y())) { // NaN: a gap in the line, as QCPGraph draws it
            flush();
            haveLast = false;
            continue;
        }
        const int x = inside(p) ? int(std::floor(p.x())) : INT_MIN;
        if (haveLast && x != INT_MIN && x == column) { // the line stays in this column: it grows
            high = std::min(high, p.y());
            low = std::max(low, p.y());
        } else if (haveLast && x != INT_MIN && column != INT_MIN && x == column + 1) {
            flush(); // the step into the next column is drawn by that column, from the last point's row
            column = x;
            high = std::min(last.y(), p.y());
            low = std::max(last.y(), p.y());
        } else {
            flush();
            QPointF a = last;
            QPointF b = p;
            if (haveLast && clipToColumns(a, b, left, right)) painter->drawLine(a, b); // across empty columns
            if (x != INT_MIN) {
                column = x;
                high = low = p.y();
            }
        }
        last = p;
        haveLast = true;
    }
    flush();
    band();
    // One call: the raster engine fills each rectangle directly, without a QPainter call's overhead each.
    painter->setPen(Qt::NoPen);
    painter->setBrush(colour);
    painter->drawRects(m_rects.constData(), int(m_rects.size()));
}

} // namespace scope
