// The two scope cursors' readout, widget-free: A and B, Δt and 1/Δt as a frequency, each channel's value at
// both cursor times (linearly interpolated between samples) and the difference, as the lines under the plot
// show them — of a capture, or of a store's live (time, value) samples.
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
    double first_s = 0;  // cursor A
    double second_s = 0; // cursor B
    double delta_s = 0;  // B - A
    std::vector<Row> rows;

    // 1/|Δt| in Hz: the frequency of a period read between two peaks; 0 when the cursors coincide.
    double frequency_hz() const;
    // One line of times, then the channels, kRowsPerLine a line:
    //   "A 5.00 ms   B 25.00 ms   Δt 20.00 ms   1/Δt 50.0 Hz"
    //   "VFB 1000 → 1000  Δy 0 VEL     ICMD 2.5 → -2.5  Δy -5 %"
    std::string text() const;
    static constexpr std::size_t kRowsPerLine = 4;
};

// "20.00 ms", "1.2500 s", "250.0 µs": a time or time difference as the readout writes it.
std::string formatSeconds(double seconds);
// "50.0 Hz", "2.00 kHz", "0.500 Hz": a frequency as the readout writes it.
std::string formatHertz(double hertz);

// The channel's value at time t (clamped to the record), interpolated; 0 for an empty channel.
double valueAt(const Capture& capture, std::size_t channel, double t_s);
CursorReadout readCursors(const Capture& capture, double first_s, double second_s);
// The same over samples at their own times (clamped to the first and last), as live traces hold them.
double valueAt(const Channel& channel, double t_s);
CursorReadout readCursors(const SeriesStore& store, double first_s, double second_s);

} // namespace scope
