// Math channels, widget-free: A + B, A - B, k A, d/dt, integral, moving average and following error, each
// yielding a new channel in its operands' representation (a capture's CaptureChannel, or a store's timed
// Channel). Decisions:
// - Units: A +- B and following error need equal unit strings (compared exactly; "" is a unit of its own),
//   else UnitMismatch. k A keeps A's unit unless a new one is given (k is dimensionless). d/dt divides by
//   seconds and the integral multiplies by them, as a power of s on the unit: "rpm" -> "rpm/s" -> "rpm/s²",
//   "rpm" -> "rpm·s", "rpm/s" integrated -> "rpm", "" -> "1/s" or "s".
// - Derivative: per second, central differences (y[i+1] - y[i-1]) / (t[i+1] - t[i-1]); one-sided at both
//   ends. Integral: trapezoidal, cumulative, 0 at the first sample.
// - Moving average: trailing (causal, like a drive's filter) over the last N samples; the first N - 1
//   outputs average the samples so far.
// - Two operands of a capture must have the same length (LengthMismatch). Of a store: B is linearly
//   interpolated at A's sample times; A's samples outside B's time span are left out (NoOverlap if none
//   remain). Following error is command - feedback.
// - Default names: "A+B", "A-B", "2*A", "d/dt(A)", "∫(A)", "avg8(A)", "FE(CMD-FB)" (no commas: .CSV-safe).
#pragma once

#include "capture.h"
#include "series_store.h"

#include <cstddef>
#include <optional>
#include <string>

namespace scope {

enum class MathStatus {
    Ok,
    UnitMismatch,   // A +- B, following error: the operands' units differ
    LengthMismatch, // two capture channels of different lengths
    NoOverlap,      // two store channels with no common time span
    TooShort,       // derivative of fewer than 2 samples
    BadParameter,   // k not finite, moving-average window 0
    UnknownChannel, // evaluate(): an operand named in the spec is not there
};

template <typename ChannelType> struct MathResult {
    MathStatus status = MathStatus::Ok;
    std::string error; // in words, naming the operands; empty when Ok
    ChannelType channel;
    bool ok() const { return status == MathStatus::Ok; }
};
using CaptureMath = MathResult<CaptureChannel>; // sampled at the capture's interval_s
using TraceMath = MathResult<Channel>;          // samples at their own times

// The unit of d/dt and of the integral over time of a channel in `unit`.
std::string derivativeUnit(const std::string& unit);
std::string integralUnit(const std::string& unit);

// On a capture's channels (sampled together every interval_s).
CaptureMath sum(const CaptureChannel& a, const CaptureChannel& b);
CaptureMath difference(const CaptureChannel& a, const CaptureChannel& b);
CaptureMath scaled(const CaptureChannel& a, double k, const std::optional<std::string>& unit = std::nullopt);
CaptureMath derivative(const CaptureChannel& a, double interval_s);
CaptureMath integral(const CaptureChannel& a, double interval_s);
CaptureMath movingAverage(const CaptureChannel& a, std::size_t samples);
CaptureMath followingError(const CaptureChannel& command, const CaptureChannel& feedback);

// On a store's channels, at their samples' own times.
TraceMath sum(const Channel& a, const Channel& b);
TraceMath difference(const Channel& a, const Channel& b);
TraceMath scaled(const Channel& a, double k, const std::optional<std::string>& unit = std::nullopt);
TraceMath derivative(const Channel& a);
TraceMath integral(const Channel& a);
TraceMath movingAverage(const Channel& a, std::size_t samples);
TraceMath followingError(const Channel& command, const Channel& feedback);

// A math channel as the user defines it (by operand names), re-evaluated on every new capture or trace.
enum class MathOp { Sum, Difference, Scale, Derivative, Integral, MovingAverage, FollowingError };

struct MathChannelSpec {
    MathOp op = MathOp::Sum;
    std::string a;                   // first operand; the command for FollowingError
    std::string b;                   // second operand (Sum, Difference; the feedback for FollowingError)
    double k = 1;                    // Scale
    std::optional<std::string> unit; // Scale: the result's unit; unset keeps A's
    std::size_t window = 8;          // MovingAverage: N samples
    std::string name;                // the result's name; empty: the default name above
};

CaptureMath evaluate(const Capture& capture, const MathChannelSpec& spec);
TraceMath evaluate(const SeriesStore& store, const MathChannelSpec& spec);

} // namespace scope
