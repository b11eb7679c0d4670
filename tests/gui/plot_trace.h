// traceIn: how much of a plot area in a screenshot is plotted trace — pixels of a saturated colour far from
// the area's background — as opposed to background, grid, axes, cursors and text, which are all grey.
#pragma once

#include <QImage>
#include <QRect>

struct TraceCount {
    int pixels = 0;  // trace pixels in the area
    int columns = 0; // columns of the area with at least one: a trace runs across, a marker line does not
};

// The trace pixels of image (ARGB32) inside area (pixels), the background being the area's most common colour.
TraceCount traceIn(const QImage& image, const QRect& area);
