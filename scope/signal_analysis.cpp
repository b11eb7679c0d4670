// Channel statistics and step-response metrics.
//
// Step window: with a command, the step starts at the command's first change (more than 0.1 % of its range
// away from its first value) and the window ends where the command first turns back towards its first value
// (the J 0 after a velocity step, the return move of a position step); without one, the whole record is the
// window and the step starts where the response first leaves 2 % of its final change. Within the window:
//   step size   = finalValue - initial
//   overshoot % = how far the response goes past finalValue, in % of |step size|
//   rise time   = first 10 % crossing to first 90 % crossing of the step, linearly interpolated
//   settling    = from the step start to the first sample after the last one outside finalValue +- 2 %;
//                 unset when the response is still outside the band at the window's last sample.
#include "signal_analysis.h"

#include <algorithm>
#include <cmath>

namespace scope {

namespace {

constexpr double kSettleBand = 0.02;
constexpr double kFinalShare = 0.10;

// Time at which the response first crosses initial + fraction * step, from index `from`, interpolated.
std::optional<double> crossing(std::span<const double> y, std::size_t from, std::size_t end, double initial,
                               double step, double fraction, double dt) {
    const double level = initial + fraction * step;
    for (std::size_t i = std::max<std::size_t>(from, 1); i < end; ++i) {
        const double a = (y[i - 1] - level) * (step > 0 ? 1 : -1);
        const double b = (y[i] - level) * (step > 0 ? 1 : -1);
        if (b >= 0 && a < 0) return (double(i - 1) + (-a) / (b - a)) * dt;
    }
    if (from == 0 && !y.empty() && (y[0] - level) * (step > 0 ? 1 : -1) >= 0) return 0.0;
    return std::nullopt;
}

} // namespace

std::optional<ChannelStats> channelStats(std::span<const double> values) {
    if (values.empty()) return std::nullopt;
    ChannelStats s;
    s.minimum = *std::min_element(values.begin(), values.end());
    s.maximum = *std::max_element(values.begin(), values.end());
    double sum = 0, squares = 0;
    for (const double v : values) {
        sum += v;
        squares += v * v;
    }
    s.mean = sum / double(values.size());
    s.rms = std::sqrt(squares / double(values.size()));
    s.peakToPeak = s.maximum - s.minimum;
    return s;
}

StepMetrics analyseStep(std::span<const double> y, double dt, std::span<const double> command) {
    StepMetrics m;
    const std::size_t n = y.size();
    if (n < 2) return m;
    const bool withCommand = command.size() == n;
    std::size_t start = 0;
    std::size_t end = n;
    if (withCommand) {
        const auto [lo, hi] = std::minmax_element(command.begin(), command.end());
        const double tolerance = std::max(1e-12, 1e-3 * (*hi - *lo));
        const double c0 = command[0];
        while (start < n && std::abs(command[start] - c0) <= tolerance) ++start;
        if (start == n) return m; // the command never moved
        start = start > 0 ? start - 1 : 0;
        for (std::size_t i = start + 1; i < n; ++i) {
            if (std::abs(command[i] - c0) < std::abs(command[i - 1] - c0) - tolerance) {
                end = i;
                break;
            }
        }
    }
    m.initial = y[0];
    const std::size_t tail = std::max<std::size_t>(1, std::size_t(double(end - start) * kFinalShare));
    double sum = 0;
    for (std::size_t i = end - tail; i < end; ++i) sum += y[i];
    m.finalValue = sum / double(tail);
    const double step = m.finalValue - m.initial;
    const double scale = std::max({std::abs(m.initial), std::abs(m.finalValue), 1.0});
    if (std::abs(step) <= 1e-9 * scale) return m;
    m.hasStep = true;
    const double band = kSettleBand * std::abs(step);
    if (!withCommand) {
        while (start + 1 < end && std::abs(y[start + 1] - m.initial) <= band) ++start;
    }
    m.stepStart_s = double(start) * dt;
    m.windowEnd_s = double(end - 1) * dt;

    double peakPast = 0; // how far past finalValue, in the step's direction
    for (std::size_t i = start; i < end; ++i)
        peakPast = std::max(peakPast, (y[i] - m.finalValue) * (step > 0 ? 1 : -1));
    m.overshoot_pct = 100.0 * peakPast / std::abs(step);

    const auto t10 = crossing(y, start, end, m.initial, step, 0.1, dt);
    const auto t90 = crossing(y, start, end, m.initial, step, 0.9, dt);
    if (t10 && t90 && *t90 >= *t10) m.rise_s = *t90 - *t10;

    std::optional<std::size_t> lastOutside;
    for (std::size_t i = start; i < end; ++i)
        if (std::abs(y[i] - m.finalValue) > band) lastOutside = i;
    if (!lastOutside)
        m.settling_s = 0.0;
    else if (*lastOutside + 1 < end)
        m.settling_s = double(*lastOutside + 1 - start) * dt;

    if (withCommand) {
        m.steadyStateError = command[end - 1] - m.finalValue;
        double peak = 0;
        for (std::size_t i = 0; i < n; ++i) peak = std::max(peak, std::abs(command[i] - y[i]));
        m.followingErrorPeak = peak;
    }
    return m;
}

} // namespace scope
