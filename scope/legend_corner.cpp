// The legend's corner: Liang-Barsky clipping of each segment against the candidate boxes.
#include "legend_corner.h"

#include <array>
#include <cmath>

namespace scope {

PixelBox legendBox(const PixelBox& area, double legendWidth, double legendHeight, double margin, LegendCorner corner) {
    const bool right = corner == LegendCorner::TopRight || corner == LegendCorner::BottomRight;
    const bool bottom = corner == LegendCorner::BottomRight || corner == LegendCorner::BottomLeft;
    return {right ? area.left + area.width - margin - legendWidth : area.left + margin,
            bottom ? area.top + area.height - margin - legendHeight : area.top + margin, legendWidth, legendHeight};
}

namespace {

bool finite(const PixelPoint& p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

bool inside(const PixelPoint& p, const PixelBox& b) {
    return p.x >= b.left && p.x <= b.left + b.width && p.y >= b.top && p.y <= b.top + b.height;
}

// Whether the segment a-b meets the box (Liang-Barsky: the parameter interval left after the four edges).
bool crosses(const PixelPoint& a, const PixelPoint& b, const PixelBox& box) {
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const std::array<double, 4> p{-dx, dx, -dy, dy};
    const std::array<double, 4> q{a.x - box.left, box.left + box.width - a.x, a.y - box.top, box.top + box.height - a.y};
    double from = 0;
    double to = 1;
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false; // parallel to this edge and outside it
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0) from = t > from ? t : from;
        else to = t < to ? t : to;
        if (from > to) return false;
    }
    return true;
}

} // namespace

int segmentsThrough(const std::vector<std::vector<PixelPoint>>& traces, const PixelBox& box) {
    int count = 0;
    for (const std::vector<PixelPoint>& trace : traces) {
        if (trace.size() == 1 && inside(trace.front(), box)) ++count;
        for (std::size_t i = 1; i < trace.size(); ++i) // a gap (NaN) in the data is drawn as none
            if (finite(trace[i - 1]) && finite(trace[i]) && crosses(trace[i - 1], trace[i], box)) ++count;
    }
    return count;
}

LegendCorner bestLegendCorner(const std::vector<std::vector<PixelPoint>>& traces, const PixelBox& area,
                              double legendWidth, double legendHeight, double margin, LegendCorner current) {
    const auto hidden = [&](LegendCorner corner) {
        return segmentsThrough(traces, legendBox(area, legendWidth, legendHeight, margin, corner));
    };
    const int here = hidden(current);
    if (here == 0) return current;
    LegendCorner best = current;
    int least = here;
    for (const LegendCorner corner :
         {LegendCorner::TopLeft, LegendCorner::TopRight, LegendCorner::BottomRight, LegendCorner::BottomLeft}) {
        if (const int n = hidden(corner); n < least) {
            least = n;
            best = corner;
        }
    }
    return best;
}

} // namespace scope
