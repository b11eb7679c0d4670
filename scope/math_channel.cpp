// Math channels: the arithmetic once over (time, value) arrays, wrapped for captures and store channels.
#include "math_channel.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <utility>
#include <vector>

namespace scope {

namespace {

// ---- Units: a base and a power of seconds written as a suffix ("rpm/s²" = rpm, -2).

constexpr std::array<std::pair<const char*, int>, 6> kSecondSuffixes{
    {{"/s²", -2}, {"/s³", -3}, {"/s", -1}, {"·s²", 2}, {"·s³", 3}, {"·s", 1}}};

std::pair<std::string, int> splitSeconds(const std::string& unit) {
    if (unit == "s") return {"", 1}; // seconds alone: what the integral of a unitless channel gives
    if (unit == "s²") return {"", 2};
    if (unit == "s³") return {"", 3};
    for (const auto& [suffix, power] : kSecondSuffixes) {
        const std::string s(suffix);
        if (unit.size() > s.size() && unit.compare(unit.size() - s.size(), s.size(), s) == 0)
            return {unit.substr(0, unit.size() - s.size()), power};
    }
    return {unit, 0};
}

std::string joinSeconds(const std::string& base, int power) {
    const std::string b = base == "1" && power >= 0 ? "" : base;
    if (power == 0) return b;
    const int magnitude = power < 0 ? -power : power;
    const std::string s = magnitude == 1   ? "s"
                          : magnitude == 2 ? "s²"
                          : magnitude == 3 ? "s³"
                                           : "s^" + std::to_string(magnitude);
    if (power < 0) return (b.empty() ? "1" : b) + "/" + s;
    return b.empty() ? s : b + "·" + s;
}

std::string number(double k) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, k);
    return ec == std::errc() ? std::string(buffer, end) : std::string("k");
}

// ---- The arithmetic over arrays; t(i) is sample i's time in seconds.

template <typename TimeAt> std::vector<double> differentiate(const std::vector<double>& y, TimeAt t) {
    const std::size_t n = y.size();
    std::vector<double> d(n);
    d.front() = (y[1] - y[0]) / (t(1) - t(0));
    for (std::size_t i = 1; i + 1 < n; ++i) d[i] = (y[i + 1] - y[i - 1]) / (t(i + 1) - t(i - 1));
    d.back() = (y[n - 1] - y[n - 2]) / (t(n - 1) - t(n - 2));
    return d;
}

template <typename TimeAt> std::vector<double> integrate(const std::vector<double>& y, TimeAt t) {
    std::vector<double> out(y.size());
    double area = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (i > 0) area += 0.5 * (y[i] + y[i - 1]) * (t(i) - t(i - 1));
        out[i] = area;
    }
    return out;
}

std::vector<double> average(const std::vector<double>& y, std::size_t window) {
    std::vector<double> out(y.size());
    double sum = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        sum += y[i];
        if (i >= window) sum -= y[i - window];
        out[i] = sum / double(std::min(i + 1, window));
    }
    return out;
}

template <typename Result> Result fail(MathStatus status, std::string why) {
    Result r;
    r.status = status;
    r.error = std::move(why);
    return r;
}

template <typename Result, typename ChannelType>
std::optional<Result> unitsDiffer(const ChannelType& a, const ChannelType& b, const char* what) {
    if (a.unit == b.unit) return std::nullopt;
    return fail<Result>(MathStatus::UnitMismatch, std::string(what) + " of " + a.name + " (" +
                                                      (a.unit.empty() ? "no unit" : a.unit) + ") and " + b.name + " (" +
                                                      (b.unit.empty() ? "no unit" : b.unit) + "): the units differ");
}

// ---- Captures.

CaptureMath binary(const CaptureChannel& a, const CaptureChannel& b, double signOfB, std::string name,
                   const char* what) {
    if (auto refused = unitsDiffer<CaptureMath>(a, b, what)) return *refused;
    if (a.values.size() != b.values.size())
        return fail<CaptureMath>(MathStatus::LengthMismatch, std::string(what) + " of " + a.name + " (" +
                                                                 std::to_string(a.values.size()) + " samples) and " +
                                                                 b.name + " (" + std::to_string(b.values.size()) +
                                                                 " samples): the lengths differ");
    CaptureMath r;
    r.channel = {std::move(name), a.unit, std::vector<double>(a.values.size())};
    for (std::size_t i = 0; i < a.values.size(); ++i) r.channel.values[i] = a.values[i] + signOfB * b.values[i];
    return r;
}

std::optional<CaptureMath> badInterval(double interval_s) {
    if (std::isfinite(interval_s) && interval_s > 0) return std::nullopt;
    return fail<CaptureMath>(MathStatus::BadParameter, "the sample interval must be a positive time");
}

// ---- Store channels.

std::vector<double> valuesOf(const Channel& c) {
    std::vector<double> v;
    v.reserve(c.samples.size());
    for (const Sample& s : c.samples) v.push_back(s.value);
    return v;
}

Channel withValues(const Channel& like, std::string name, std::string unit, const std::vector<double>& values) {
    Channel out{std::move(name), std::move(unit), {}};
    for (std::size_t i = 0; i < values.size(); ++i) out.samples.push_back({like.samples[i].time_s, values[i]});
    return out;
}

// a + signOfB * b(t) at a's times within b's span, b linearly interpolated (exact at b's own times).
TraceMath binary(const Channel& a, const Channel& b, double signOfB, std::string name, const char* what) {
    if (auto refused = unitsDiffer<TraceMath>(a, b, what)) return *refused;
    TraceMath r;
    r.channel = {std::move(name), a.unit, {}};
    const auto& bs = b.samples;
    std::size_t j = 0;
    for (const Sample& s : a.samples) {
        if (bs.empty() || s.time_s < bs.front().time_s || s.time_s > bs.back().time_s) continue;
        while (j + 1 < bs.size() && bs[j + 1].time_s <= s.time_s) ++j;
        double bv = bs[j].value;
        if (s.time_s > bs[j].time_s && j + 1 < bs.size())
            bv += (bs[j + 1].value - bs[j].value) * (s.time_s - bs[j].time_s) / (bs[j + 1].time_s - bs[j].time_s);
        r.channel.samples.push_back({s.time_s, s.value + signOfB * bv});
    }
    if (r.channel.samples.empty() && !a.samples.empty())
        return fail<TraceMath>(MathStatus::NoOverlap,
                               std::string(what) + " of " + a.name + " and " + b.name + ": no common time span");
    return r;
}

} // namespace

std::string derivativeUnit(const std::string& unit) {
    const auto [base, power] = splitSeconds(unit);
    return joinSeconds(base, power - 1);
}

std::string integralUnit(const std::string& unit) {
    const auto [base, power] = splitSeconds(unit);
    return joinSeconds(base, power + 1);
}

CaptureMath sum(const CaptureChannel& a, const CaptureChannel& b) {
    return binary(a, b, 1, a.name + "+" + b.name, "sum");
}

CaptureMath difference(const CaptureChannel& a, const CaptureChannel& b) {
    return binary(a, b, -1, a.name + "-" + b.name, "difference");
}

CaptureMath followingError(const CaptureChannel& command, const CaptureChannel& feedback) {
    return binary(command, feedback, -1, "FE(" + command.name + "-" + feedback.name + ")", "following error");
}

CaptureMath scaled(const CaptureChannel& a, double k, const std::optional<std::string>& unit) {
    if (!std::isfinite(k)) return fail<CaptureMath>(MathStatus::BadParameter, "the factor must be a finite number");
    CaptureMath r;
    r.channel = {number(k) + "*" + a.name, unit.value_or(a.unit), a.values};
    for (double& v : r.channel.values) v *= k;
    return r;
}

CaptureMath derivative(const CaptureChannel& a, double interval_s) {
    if (auto refused = badInterval(interval_s)) return *refused;
    if (a.values.size() < 2)
        return fail<CaptureMath>(MathStatus::TooShort, "d/dt of " + a.name + ": needs at least 2 samples");
    const auto t = [interval_s](std::size_t i) { return double(i) * interval_s; };
    return {MathStatus::Ok, {}, {"d/dt(" + a.name + ")", derivativeUnit(a.unit), differentiate(a.values, t)}};
}

CaptureMath integral(const CaptureChannel& a, double interval_s) {
    if (auto refused = badInterval(interval_s)) return *refused;
    const auto t = [interval_s](std::size_t i) { return double(i) * interval_s; };
    return {MathStatus::Ok, {}, {"∫(" + a.name + ")", integralUnit(a.unit), integrate(a.values, t)}};
}

CaptureMath movingAverage(const CaptureChannel& a, std::size_t samples) {
    if (samples == 0) return fail<CaptureMath>(MathStatus::BadParameter, "a moving average needs at least 1 sample");
    return {
        MathStatus::Ok, {}, {"avg" + std::to_string(samples) + "(" + a.name + ")", a.unit, average(a.values, samples)}};
}

TraceMath sum(const Channel& a, const Channel& b) {
    return binary(a, b, 1, a.name + "+" + b.name, "sum");
}

TraceMath difference(const Channel& a, const Channel& b) {
    return binary(a, b, -1, a.name + "-" + b.name, "difference");
}

TraceMath followingError(const Channel& command, const Channel& feedback) {
    return binary(command, feedback, -1, "FE(" + command.name + "-" + feedback.name + ")", "following error");
}

TraceMath scaled(const Channel& a, double k, const std::optional<std::string>& unit) {
    if (!std::isfinite(k)) return fail<TraceMath>(MathStatus::BadParameter, "the factor must be a finite number");
    TraceMath r;
    r.channel = {number(k) + "*" + a.name, unit.value_or(a.unit), a.samples};
    for (Sample& s : r.channel.samples) s.value *= k;
    return r;
}

TraceMath derivative(const Channel& a) {
    if (a.samples.size() < 2)
        return fail<TraceMath>(MathStatus::TooShort, "d/dt of " + a.name + ": needs at least 2 samples");
    for (std::size_t i = 1; i < a.samples.size(); ++i)
        if (!(a.samples[i].time_s > a.samples[i - 1].time_s))
            return fail<TraceMath>(MathStatus::BadParameter, "d/dt of " + a.name + ": two samples at one time, t = " +
                                                                 number(a.samples[i].time_s) + " s");
    const auto t = [&a](std::size_t i) { return a.samples[i].time_s; };
    return {MathStatus::Ok,
            {},
            withValues(a, "d/dt(" + a.name + ")", derivativeUnit(a.unit), differentiate(valuesOf(a), t))};
}

TraceMath integral(const Channel& a) {
    const auto t = [&a](std::size_t i) { return a.samples[i].time_s; };
    return {MathStatus::Ok, {}, withValues(a, "∫(" + a.name + ")", integralUnit(a.unit), integrate(valuesOf(a), t))};
}

TraceMath movingAverage(const Channel& a, std::size_t samples) {
    if (samples == 0) return fail<TraceMath>(MathStatus::BadParameter, "a moving average needs at least 1 sample");
    return {MathStatus::Ok,
            {},
            withValues(a, "avg" + std::to_string(samples) + "(" + a.name + ")", a.unit, average(valuesOf(a), samples))};
}

namespace {

// One evaluate() for both representations: find operands by name, apply the op, rename.
template <typename Result, typename Find, typename OverTime>
Result evaluateWith(const MathChannelSpec& spec, Find find, OverTime derivativeOrIntegral) {
    const auto* a = find(spec.a);
    if (!a) return fail<Result>(MathStatus::UnknownChannel, "no channel named \"" + spec.a + "\"");
    const bool twoOperands =
        spec.op == MathOp::Sum || spec.op == MathOp::Difference || spec.op == MathOp::FollowingError;
    const auto* b = twoOperands ? find(spec.b) : a;
    if (!b) return fail<Result>(MathStatus::UnknownChannel, "no channel named \"" + spec.b + "\"");
    Result r;
    switch (spec.op) {
    case MathOp::Sum: r = sum(*a, *b); break;
    case MathOp::Difference: r = difference(*a, *b); break;
    case MathOp::FollowingError: r = followingError(*a, *b); break;
    case MathOp::Scale: r = scaled(*a, spec.k, spec.unit); break;
    case MathOp::MovingAverage: r = movingAverage(*a, spec.window); break;
    case MathOp::Derivative:
    case MathOp::Integral: r = derivativeOrIntegral(*a, spec.op == MathOp::Derivative); break;
    }
    if (r.ok() && !spec.name.empty()) r.channel.name = spec.name;
    return r;
}

} // namespace

CaptureMath evaluate(const Capture& capture, const MathChannelSpec& spec) {
    return evaluateWith<CaptureMath>(
        spec, [&capture](const std::string& name) { return capture.find(name); },
        [&capture](const CaptureChannel& a, bool d) {
            return d ? derivative(a, capture.interval_s) : integral(a, capture.interval_s);
        });
}

TraceMath evaluate(const SeriesStore& store, const MathChannelSpec& spec) {
    return evaluateWith<TraceMath>(
        spec,
        [&store](const std::string& name) -> const Channel* {
            const auto index = store.find(name);
            return index ? &store.channel(*index) : nullptr;
        },
        [](const Channel& a, bool d) { return d ? derivative(a) : integral(a); });
}

} // namespace scope
