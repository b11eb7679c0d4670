// SeriesStore: channels of time-ordered samples.
#include "series_store.h"

#include <algorithm>

namespace scope {

std::size_t SeriesStore::addChannel(const std::string& name, const std::string& unit) {
    if (const auto existing = find(name)) return *existing;
    m_channels.push_back(Channel{name, unit, {}});
    return m_channels.size() - 1;
}

std::optional<std::size_t> SeriesStore::find(const std::string& name) const {
    for (std::size_t i = 0; i < m_channels.size(); ++i)
        if (m_channels[i].name == name) return i;
    return std::nullopt;
}

bool SeriesStore::append(std::size_t channel, Sample sample) {
    Channel& c = m_channels.at(channel);
    if (!c.samples.empty() && sample.time_s < c.samples.back().time_s) return false;
    c.samples.push_back(sample);
    if (c.samples.size() > m_capacity) c.samples.pop_front();
    return true;
}

void SeriesStore::dropBefore(double time_s) {
    for (Channel& c : m_channels)
        while (!c.samples.empty() && c.samples.front().time_s < time_s) c.samples.pop_front();
}

void SeriesStore::clear() {
    for (Channel& c : m_channels) c.samples.clear();
}

std::optional<ValueRange> SeriesStore::valueRange(std::size_t channel, double from_s, double to_s) const {
    const auto& s = m_channels.at(channel).samples;
    // Samples are time-ordered: binary search the window instead of scanning everything.
    auto first = std::lower_bound(s.begin(), s.end(), from_s, [](const Sample& a, double t) { return a.time_s < t; });
    auto last = std::upper_bound(first, s.end(), to_s, [](double t, const Sample& a) { return t < a.time_s; });
    if (first == last) return std::nullopt;
    const auto [lo, hi] =
        std::minmax_element(first, last, [](const Sample& a, const Sample& b) { return a.value < b.value; });
    return ValueRange{lo->value, hi->value};
}

} // namespace scope
