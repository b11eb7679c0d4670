// Where a plot's legend hides the least of the traces, widget-free. The legend sits in a corner of the plot
// area; a step that starts at the left edge and rises to the top runs under a top-left legend (the PMC-960's
// tach rise in its tuning view did). Each trace is a polyline in pixels; a corner scores the segments that
// cross the legend's box there. The legend moves only to a corner that hides strictly less than where it is,
// so a live trace does not make it jump back and forth.
#pragma once

#include <vector>

namespace scope {

enum class LegendCorner { TopLeft, TopRight, BottomRight, BottomLeft };

struct PixelPoint {
    double x = 0;
    double y = 0; // down, as on the screen
};

struct PixelBox {
    double left = 0;
    double top = 0;
    double width = 0;
    double height = 0;
};

// The legend's box in `corner` of `area`, `margin` pixels in from its edges.
PixelBox legendBox(const PixelBox& area, double legendWidth, double legendHeight, double margin, LegendCorner corner);

// How many segments of the polylines cross or touch `box` (a lone point counts when inside; a segment to or
// from a NaN point, a gap, does not).
int segmentsThrough(const std::vector<std::vector<PixelPoint>>& traces, const PixelBox& box);

// The corner for the legend: `current` while nothing hides under it or no corner hides less; otherwise the one
// that hides the least, the first of top left, top right, bottom right, bottom left on a tie.
LegendCorner bestLegendCorner(const std::vector<std::vector<PixelPoint>>& traces, const PixelBox& area,
                              double legendWidth, double legendHeight, double margin, LegendCorner current);

} // namespace scope
