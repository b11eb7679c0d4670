// Measurements of recorded channels, widget-free: statistics of one channel, and the step-response
// figures of a feedback channel against its command (overshoot, 10-90 % rise, 2 % settling, steady-state
// error, following-error peak). Definitions are in signal_analysis.cpp, next to the code.
#pragma once

#include <optional>
#include <span>

namespace scope {

struct ChannelStats {
    double minimum = 0;
    double maximum = 0;
    double mean = 0;
    double rms = 0;
    double peakToPeak = 0;
};

// nullopt for an empty channel.
std::optional<ChannelStats> channelStats(std::span<const double> values);

struct StepMetrics {
    bool hasStep = false;             // false: the response (or its command) never moved; the rest is unset
    double initial = 0;               // response at the first sample
    double finalValue = 0;            // mean response over the last 10 % of the step window
    double stepStart_s = 0;           // when the command (or, without one, the response) starts to move
    double windowEnd_s = 0;           // end of the analysed step: the command's first move back, or the record's end
    double overshoot_pct = 0;         // of the step size, past the final value; 0 when it never passes it
    std::optional<double> rise_s;     // 10 % -> 90 % of the step
    std::optional<double> settling_s; // from stepStart until it stays within 2 % of the step of finalValue
    std::optional<double> steadyStateError;   // command plateau - finalValue (only with a command)
    std::optional<double> followingErrorPeak; // largest |command - response| over the record (with a command)
};

// response and command are sampled together every interval_s; command may be empty.
StepMetrics analyseStep(std::span<const double> response, double interval_s, std::span<const double> command = {});

} // namespace scope
