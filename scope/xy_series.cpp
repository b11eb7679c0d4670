// One channel against another.
#include "xy_series.h"

#include <algorithm>

namespace scope {

namespace {
std::string title(const CaptureChannel& c) {
    return c.unit.empty() ? c.name : c.name + " [" + c.unit + "]";
}
} // namespace

XySeries xySeries(const Capture& capture, std::size_t xChannel, std::size_t yChannel) {
    XySeries s;
    if (xChannel >= capture.channels.size() || yChannel >= capture.channels.size()) return s;
    const CaptureChannel& x = capture.channels[xChannel];
    const CaptureChannel& y = capture.channels[yChannel];
    const std::size_t n = std::min(x.values.size(), y.values.size());
    s.x.assign(x.values.begin(), x.values.begin() + std::ptrdiff_t(n));
    s.y.assign(y.values.begin(), y.values.begin() + std::ptrdiff_t(n));
    s.xTitle = title(x);
    s.yTitle = title(y);
    return s;
}

} // namespace scope
