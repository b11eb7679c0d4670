// SVG drawing of a scope view.
#include "svg_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace scope {

namespace {
constexpr double kMargin = 50;

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.2f", v);
    return b;
}

std::string escape(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '&': out += "&amp;"; break;
        default: out += c;
        }
    }
    return out;
}
} // namespace

std::string writeSvg(const SvgPlot& plot) {
    const double w = plot.width, h = plot.height;
    const double left = kMargin, right = w - kMargin, top = 20, bottom = h - 40;
    const double span = std::max(plot.timeTo_s - plot.timeFrom_s, 1e-12);
    auto x = [&](double t) { return left + (t - plot.timeFrom_s) / span * (right - left); };
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      std::to_string(plot.width) + "\" height=\"" + std::to_string(plot.height) +
                      "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" "
                      "fill=\"white\"/>\n<rect x=\"" +
                      num(left) + "\" y=\"" + num(top) + "\" width=\"" + num(right - left) + "\" height=\"" +
                      num(bottom - top) + "\" fill=\"none\" stroke=\"#3c4043\"/>\n";
    for (int i = 0; i <= 5; ++i) {
        const double t = plot.timeFrom_s + span * i / 5;
        out += "<line x1=\"" + num(x(t)) + "\" y1=\"" + num(top) + "\" x2=\"" + num(x(t)) + "\" y2=\"" + num(bottom) +
               "\" stroke=\"#e0e0e0\" stroke-dasharray=\"2,2\"/>\n<text x=\"" + num(x(t)) + "\" y=\"" +
               num(bottom + 14) + "\" text-anchor=\"middle\">" + num(t) + "</text>\n";
    }
    out +=
        "<text x=\"" + num((left + right) / 2) + "\" y=\"" + num(h - 8) + "\" text-anchor=\"middle\">Time [s]</text>\n";
    double legendY = top + 14;
    for (const SvgPlot::Channel& c : plot.channels) {
        if (!c.channel) continue;
        const double range = std::abs(c.to - c.from) > 1e-12 ? c.to - c.from : 1.0;
        out += "<polyline fill=\"none\" stroke=\"" + c.colour + "\" stroke-width=\"1.5\" points=\"";
        const auto& v = c.channel->values;
        for (std::size_t i = 0; i < v.size(); ++i) {
            const double t = plot.start_s + double(i) * plot.interval_s;
            if (t < plot.timeFrom_s - plot.interval_s || t > plot.timeTo_s + plot.interval_s) continue;
            const double y = std::clamp(bottom - (v[i] - c.from) / range * (bottom - top), top, bottom);
            out += num(x(t)) + "," + num(y) + " ";
        }
        out += "\"/>\n<text x=\"" + num(right - 8) + "\" y=\"" + num(legendY) + "\" text-anchor=\"end\" fill=\"" +
               c.colour + "\">" + escape(c.channel->name) +
               (c.channel->unit.empty() ? "" : " [" + escape(c.channel->unit) + "]") + "  " + num(c.from) + " .. " +
               num(c.to) + "</text>\n";
        legendY += 14;
    }
    return out + "</svg>\n";
}

} // namespace scope
