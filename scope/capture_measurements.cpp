// Measurements of every channel of a capture.
#include "capture_measurements.h"

namespace scope {

std::string commandOf(const std::string& feedback) {
    if (feedback == "VFB") return "VCMD";
    if (feedback == "PFB") return "PCMD";
    return {};
}

std::vector<ChannelMeasurements> measure(const Capture& capture) {
    std::vector<ChannelMeasurements> out;
    for (const CaptureChannel& c : capture.channels) {
        ChannelMeasurements m;
        m.name = c.name;
        m.unit = c.unit;
        if (const auto stats = channelStats(c.values)) m.stats = *stats;
        bool isCommand = false;
        for (const CaptureChannel& other : capture.channels)
            if (commandOf(other.name) == c.name) isCommand = true;
        const CaptureChannel* command = capture.find(commandOf(c.name));
        // Step figures need a step: the channel's own command, or a capture of this channel alone.
        if (!isCommand && (command || capture.channels.size() == 1)) {
            if (command) m.commandName = command->name;
            m.step = analyseStep(c.values, capture.interval_s,
                                 command ? std::span<const double>(command->values) : std::span<const double>());
        }
        out.push_back(std::move(m));
    }
    return out;
}

} // namespace scope
