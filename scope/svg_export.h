// Scope > Export SVG, widget-free: the shown time window of a capture's channels as an SVG drawing (frame,
// time ticks, one polyline per channel scaled to its own axis range, and a legend). Qt's SVG module is not
// among the build's dependencies, so the few elements needed are written directly.
#pragma once

#include "capture.h"

#include <string>
#include <vector>

namespace scope {

struct SvgPlot {
    struct Channel {
        const CaptureChannel* channel = nullptr;
        double from = 0; // the channel's axis range
        double to = 1;
        std::string colour = "#1a73e8";
    };
    int width = 800;
    int height = 450;
    double interval_s = 0.001;
    double start_s = 0; // the time of the channels' first sample (Capture::start_s)
    double timeFrom_s = 0;
    double timeTo_s = 1;
    std::vector<Channel> channels;
};

std::string writeSvg(const SvgPlot& plot);

} // namespace scope
