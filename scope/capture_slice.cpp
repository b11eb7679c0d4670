// Time-range slices of a capture.
#include "capture_slice.h"

#include <algorithm>
#include <cmath>

namespace scope {

Capture sliceCapture(const Capture& capture, double from_s, double to_s) {
    Capture out = capture;
    const std::size_t count = capture.sampleCount();
    const double slack = capture.interval_s * 1e-6;
    // First and one-past-last sample index inside the range, from the fixed interval.
    const double first = std::ceil((from_s - capture.start_s - slack) / capture.interval_s);
    const double last = std::floor((to_s - capture.start_s + slack) / capture.interval_s);
    const auto begin = std::size_t(std::clamp(first, 0.0, double(count)));
    const auto end = std::size_t(std::clamp(last + 1, 0.0, double(count)));
    for (CaptureChannel& c : out.channels) {
        if (begin >= end) {
            c.values.clear();
            continue;
        }
        c.values.assign(c.values.begin() + std::ptrdiff_t(begin), c.values.begin() + std::ptrdiff_t(end));
    }
    out.start_s = begin < end ? capture.timeAt(begin) : capture.start_s;
    return out;
}

} // namespace scope
