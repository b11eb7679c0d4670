// Widget-free store of recorded or polled channels (time, value) with units; the plots adapt it to
// QCustomPlot. Appends are incremental; the oldest samples drop when a channel reaches its capacity.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace scope {

struct Sample {
    double time_s = 0;
    double value = 0;
};

struct Channel {
    std::string name; // "VFB"
    std::string unit; // "RPM"
    std::deque<Sample> samples;
};

struct ValueRange {
    double minimum = 0;
    double maximum = 0;
};

class SeriesStore {
public:
    explicit SeriesStore(std::size_t capacityPerChannel = 1'000'000) : m_capacity(capacityPerChannel) {}

    // Returns the channel's index; adding an existing name returns its index and keeps its data.
    std::size_t addChannel(const std::string& name, const std::string& unit);
    std::optional<std::size_t> find(const std::string& name) const;

    // Appends in time order; a sample older than the channel's last one is refused (returns false).
    bool append(std::size_t channel, Sample sample);
    // A rolling window: drops every channel's samples older than time_s.
    void dropBefore(double time_s);
    void clear();

    std::size_t channelCount() const { return m_channels.size(); }
    const Channel& channel(std::size_t index) const { return m_channels.at(index); }
    // Min and max of the values with time in [from_s, to_s]; nullopt if there are none.
    std::optional<ValueRange> valueRange(std::size_t channel, double from_s, double to_s) const;

private:
    std::size_t m_capacity;
    std::vector<Channel> m_channels;
};

} // namespace scope
