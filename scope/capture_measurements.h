// The measurements of a whole capture, as the scope's table shows them: statistics for every channel, and
// step figures for each feedback channel against its command when both were recorded (VFB against VCMD,
// PFB against PCMD); a capture of one channel gets step figures on its own; other channels (ICMD next to
// a step) get statistics only. Widget-free.
#pragma once

#include "capture.h"
#include "signal_analysis.h"

#include <optional>
#include <string>
#include <vector>

namespace scope {

struct ChannelMeasurements {
    std::string name;
    std::string unit;
    std::string commandName; // "" when measured on its own
    ChannelStats stats;
    std::optional<StepMetrics> step; // unset for a command channel
};

// "VFB" -> "VCMD", "PFB" -> "PCMD", "" otherwise.
std::string commandOf(const std::string& feedback);
std::vector<ChannelMeasurements> measure(const Capture& capture);

} // namespace scope
