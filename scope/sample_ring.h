// SampleRing: a fixed-capacity ring of multi-channel samples (time + one value per channel) under the
// triggered capture. Pushing into a full ring overwrites the oldest sample; nothing is allocated after
// construction. Index 0 is the oldest sample held. One thread at a time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace scope {

class SampleRing {
public:
    // capacity >= 1 samples of channelCount >= 1 values each (0 is taken as 1).
    SampleRing(std::size_t capacity, std::size_t channelCount);

    // values.size() must be channelCount(); missing values read 0, extra ones are ignored.
    void push(double time_s, std::span<const double> values);
    void clear();

    std::size_t capacity() const { return m_times.size(); }
    std::size_t channelCount() const { return m_channels; }
    std::size_t size() const { return m_size; }
    bool full() const { return m_size == capacity(); }
    // Samples pushed since construction or clear(), overwritten ones included: the absolute index of the
    // next push.
    std::uint64_t pushed() const { return m_pushed; }

    // i in [0, size()): 0 is the oldest held, size() - 1 the newest.
    double time(std::size_t i) const { return m_times[slot(i)]; }
    double value(std::size_t i, std::size_t channel) const { return m_values[slot(i) * m_channels + channel]; }

private:
    std::size_t slot(std::size_t i) const { return (m_oldest + i) % capacity(); }

    std::size_t m_channels;
    std::vector<double> m_times;
    std::vector<double> m_values; // capacity x channels, row per slot
    std::size_t m_oldest = 0;
    std::size_t m_size = 0;
    std::uint64_t m_pushed = 0;
};

} // namespace scope
