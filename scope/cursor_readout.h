// The two scope cursors' readout, widget-free: each channel's value at both cursor times (linearly
// interpolated between samples) and the differences, as the plot's status line shows them — of a capture, or
// of a store's live (time, value) samples.
#pragma once

#include "capture.h"
#include "series_store.h"

#include <string>
#include <vector>

namespace scope {

struct CursorReadout {
    struct Row {
        std::string name;
        std::string unit;
        double atFirst = 0;
        double atSecond = 0;
        double delta = 0; // atSecond - atFirst
    };
    double first_s = 0;
    double second_s = 0;
    double delta_s = 0; // second - first
    std::vector<Row> rows;

    // "t1 12.0 ms  t2 34.0 ms  Δt 22.0 ms   VFB Δ 480 VEL   ICMD Δ -3 I"
    std::string text() const;
};

// The channel's value at time t (clamped to the record), interpolated; 0 for an empty channel.
double valueAt(const Capture& capture, std::size_t channel, double t_s);
CursorReadout readCursors(const Capture& capture, double first_s, double second_s);
// The same over samples at their own times (clamped to the first and last), as live traces hold them.
double valueAt(const Channel& channel, double t_s);
CursorReadout readCursors(const SeriesStore& store, double first_s, double second_s);

} // namespace scope
