// SampleRing: fixed slots, the oldest overwritten.
#include "sample_ring.h"

#include <algorithm>

namespace scope {

SampleRing::SampleRing(std::size_t capacity, std::size_t channelCount)
    : m_channels(std::max<std::size_t>(channelCount, 1)), m_times(std::max<std::size_t>(capacity, 1)),
      m_values(m_times.size() * m_channels) {}

void SampleRing::push(double time_s, std::span<const double> values) {
    const std::size_t at = full() ? m_oldest : slot(m_size);
    m_times[at] = time_s;
    double* row = m_values.data() + at * m_channels;
    const std::size_t given = std::min(values.size(), m_channels);
    std::copy_n(values.begin(), given, row);
    std::fill(row + given, row + m_channels, 0.0);
    if (full())
        m_oldest = (m_oldest + 1) % capacity();
    else
        ++m_size;
    ++m_pushed;
}

void SampleRing::clear() {
    m_oldest = 0;
    m_size = 0;
    m_pushed = 0;
}

} // namespace scope
