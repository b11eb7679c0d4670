// Cursor readout: interpolation and text.
#include "cursor_readout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace scope {

namespace {
std::string number(double value, int decimals) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

// Values keep the drive's resolution: integers as integers, otherwise 3 significant decimals. A difference
// rounded to nothing reads 0, not "-0" (adding +0.0 turns -0.0 into 0).
std::string value(double v) {
    if (std::abs(v - std::round(v)) < 1e-9) return number(std::round(v) + 0.0, 0);
    return number(v, 3);
}
} // namespace

double valueAt(const Capture& capture, std::size_t channel, double t_s) {
    const auto& v = capture.channels.at(channel).values;
    if (v.empty()) return 0;
    const double position = std::clamp((t_s - capture.start_s) / capture.interval_s, 0.0, double(v.size() - 1));
    const auto i = std::size_t(position);
    if (i + 1 >= v.size()) return v.back();
    const double f = position - double(i);
    return v[i] + f * (v[i + 1] - v[i]);
}

CursorReadout readCursors(const Capture& capture, double first_s, double second_s) {
    CursorReadout r;
    r.first_s = first_s;
    r.second_s = second_s;
    r.delta_s = second_s - first_s;
    for (std::size_t c = 0; c < capture.channels.size(); ++c) {
        const double a = valueAt(capture, c, first_s);
        const double b = valueAt(capture, c, second_s);
        r.rows.push_back({capture.channels[c].name, capture.channels[c].unit, a, b, b - a});
    }
    return r;
}

double valueAt(const Channel& channel, double t_s) {
    const auto& s = channel.samples;
    if (s.empty()) return 0;
    if (t_s <= s.front().time_s) return s.front().value;
    if (t_s >= s.back().time_s) return s.back().value;
    // The first sample after t; the one before it is at or before t (times ascend, SeriesStore::append).
    const auto after =
        std::upper_bound(s.begin(), s.end(), t_s, [](double t, const Sample& x) { return t < x.time_s; });
    const Sample& a = *std::prev(after);
    const Sample& b = *after;
    const double span = b.time_s - a.time_s;
    return span > 0 ? a.value + (t_s - a.time_s) / span * (b.value - a.value) : b.value;
}

CursorReadout readCursors(const SeriesStore& store, double first_s, double second_s) {
    CursorReadout r;
    r.first_s = first_s;
    r.second_s = second_s;
    r.delta_s = second_s - first_s;
    for (std::size_t c = 0; c < store.channelCount(); ++c) {
        const Channel& channel = store.channel(c);
        const double a = valueAt(channel, first_s);
        const double b = valueAt(channel, second_s);
        r.rows.push_back({channel.name, channel.unit, a, b, b - a});
    }
    return r;
}

double CursorReadout::frequency_hz() const {
    return delta_s == 0 ? 0 : 1 / std::abs(delta_s);
}

std::string formatSeconds(double seconds) {
    const double magnitude = std::abs(seconds);
    if (magnitude >= 1) return number(seconds, 4) + " s";
    if (magnitude > 0 && magnitude < 1e-3) return number(seconds * 1e6, 1) + " \u00b5s";
    return number(seconds * 1e3, 2) + " ms";
}

std::string formatHertz(double hertz) {
    const double magnitude = std::abs(hertz);
    if (magnitude >= 1000) return number(hertz / 1000, 2) + " kHz";
    return number(hertz, magnitude >= 10 ? 1 : magnitude >= 1 ? 2 : 3) + " Hz";
}

std::string CursorReadout::text() const {
    std::string out = "A " + formatSeconds(first_s) + "   B " + formatSeconds(second_s) + "   \u0394t " +
                      formatSeconds(delta_s) + "   1/\u0394t " +
                      (delta_s == 0 ? "\u2014" : formatHertz(frequency_hz()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& row = rows[i];
        out += i % kRowsPerLine == 0 ? "\n" : "     ";
        out += row.name + " " + value(row.atFirst) + " \u2192 " + value(row.atSecond) + "  \u0394y " +
               value(row.delta) + (row.unit.empty() ? "" : " " + row.unit);
    }
    return out;
}

} // namespace scope
