// Capture: one RECORD/PLAY recording (or a .CSV loaded from disk) — up to 4 channels sampled together at a
// fixed interval, each with its drive-unit name. A plain value, widget-free; plots and analysis read it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace scope {

struct CaptureChannel {
    std::string name;           // "VFB"
    std::string unit;           // the manual's unit name: "VEL", "POS", "I", "Hz", "" for none
    std::vector<double> values; // one per sample, in the drive's user units
};

struct Capture {
    double interval_s = 0.001; // time between samples (RECORD's <Time>, in seconds)
    std::vector<CaptureChannel> channels;
    std::string title; // "Run 3: KV=2400" or the file name; free text for legends and overlays
    // When the first sample was taken: 0 for a recording; later for a slice of one (an export of the visible
    // range keeps its times, so a file of the slice plots where the slice was).
    double start_s = 0;

    std::size_t sampleCount() const { return channels.empty() ? 0 : channels.front().values.size(); }
    // Sample i is taken at start + i * interval (the first sample is taken when RECORD starts).
    double timeAt(std::size_t i) const { return start_s + double(i) * interval_s; }
    // The channel with this name, or nullptr.
    const CaptureChannel* find(const std::string& name) const {
        for (const CaptureChannel& c : channels)
            if (c.name == name) return &c;
        return nullptr;
    }
};

} // namespace scope
