// SeriesStore: channels of time-ordered samples, their min/max pyramids, and decimation per pixel column.
#include "series_store.h"

#include <algorithm>
#include <atomic>

namespace scope {

namespace {

using Samples = std::deque<Sample>;

// First sample in [first, last) at or after t_s / after t_s (times ascend).
std::size_t lowerBound(const Samples& s, std::size_t first, std::size_t last, double t_s) {
    const auto begin = s.begin() + std::ptrdiff_t(first);
    return first + std::size_t(std::partition_point(begin, s.begin() + std::ptrdiff_t(last),
                                                    [t_s](const Sample& x) { return x.time_s < t_s; }) -
                               begin);
}

std::size_t upperBound(const Samples& s, std::size_t first, std::size_t last, double t_s) {
    const auto begin = s.begin() + std::ptrdiff_t(first);
    return first + std::size_t(std::partition_point(begin, s.begin() + std::ptrdiff_t(last),
                                                    [t_s](const Sample& x) { return x.time_s <= t_s; }) -
                               begin);
}

// lowerBound, searched outwards from `guess` (doubling steps, then bisection): O(log distance), so a column
// edge costs a probe or two when the samples are evenly spaced and `guess` is proportional.
std::size_t lowerBoundNear(const Samples& s, std::size_t first, std::size_t last, std::size_t guess, double t_s) {
    guess = std::clamp(guess, first, last);
    if (guess < last && s[guess].time_s < t_s) { // after guess: in [lo, last]
        std::size_t lo = guess + 1;
        for (std::size_t step = 1;; step *= 2) {
            const std::size_t probe = std::min(lo + step - 1, last);
            if (probe == last || s[probe].time_s >= t_s) return lowerBound(s, lo, probe, t_s);
            lo = probe + 1;
        }
    }
    std::size_t hi = guess; // at or before guess: in [first, hi]
    for (std::size_t step = 1;; step *= 2) {
        if (hi == first) return first;
        const std::size_t probe = hi - first > step ? hi - step : first;
        if (s[probe].time_s < t_s) return lowerBound(s, probe + 1, hi, t_s);
        hi = probe;
    }
}

} // namespace

std::uint64_t SeriesStore::Revision::fresh() {
    static std::atomic<std::uint64_t> ranges{0};
    return (ranges.fetch_add(1, std::memory_order_relaxed) + 1) << 40;
}

std::size_t SeriesStore::addChannel(const std::string& name, const std::string& unit) {
    if (const auto existing = find(name)) return *existing;
    m_channels.push_back(Channel{name, unit, {}});
    m_pyramids.emplace_back();
    m_revision.next();
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
    MinMaxPyramid& pyramid = m_pyramids[channel];
    c.samples.push_back(sample);
    pyramid.append(sample.value);
    if (c.samples.size() > m_capacity) {
        c.samples.pop_front();
        pyramid.dropBefore(pyramid.dropped() + 1);
    }
    m_revision.next();
    return true;
}

void SeriesStore::dropBefore(double time_s) {
    for (std::size_t i = 0; i < m_channels.size(); ++i) {
        Samples& s = m_channels[i].samples;
        const std::size_t old = lowerBound(s, 0, s.size(), time_s);
        if (old == 0) continue;
        s.erase(s.begin(), s.begin() + std::ptrdiff_t(old));
        m_pyramids[i].dropBefore(m_pyramids[i].dropped() + old);
        m_revision.next();
    }
}

void SeriesStore::clear() {
    for (Channel& c : m_channels) c.samples.clear();
    for (MinMaxPyramid& p : m_pyramids) p.clear();
    m_revision.next();
}

ValueRange SeriesStore::minMax(std::size_t channel, std::size_t first, std::size_t last) const {
    const Samples& s = m_channels[channel].samples;
    const MinMaxPyramid& pyramid = m_pyramids[channel];
    constexpr std::size_t kLeaf = MinMaxPyramid::kLeafSamples;
    const std::size_t base = pyramid.dropped();
    const std::size_t leafFirst = (base + first + kLeaf - 1) / kLeaf; // whole leaf blocks inside the range
    const std::size_t leafLast = (base + last) / kLeaf;
    ValueRange range{s[first].value, s[first].value};
    const auto scan = [&](std::size_t from, std::size_t to) {
        for (auto it = s.begin() + std::ptrdiff_t(from), end = s.begin() + std::ptrdiff_t(to); it < end; ++it)
            widen(range, {it->value, it->value});
    };
    if (leafFirst >= leafLast) {
        scan(first, last);
        return range;
    }
    scan(first, leafFirst * kLeaf - base);
    scan(leafLast * kLeaf - base, last);
    widen(range, pyramid.leafRange(leafFirst, leafLast));
    return range;
}

std::optional<ValueRange> SeriesStore::valueRange(std::size_t channel, double from_s, double to_s) const {
    const auto [first, last] = indexRange(channel, from_s, to_s);
    if (first == last) return std::nullopt;
    return minMax(channel, first, last);
}

// out.size() columns from sample `first`: column j ends where a sample reaches edge(j + 1), the last one at
// `last` (so the samples [first, last) are all placed).
template <typename Edge>
void SeriesStore::fillColumns(std::size_t channel, std::size_t first, std::size_t last, Edge edge,
                              std::vector<Column>& out) const {
    const Samples& s = m_channels[channel].samples;
    const std::size_t count = out.size();
    const double perColumn = double(last - first) / double(count); // the guess: samples spread evenly
    std::size_t at = first;
    for (std::size_t j = 0; j < count; ++j) {
        const auto guess = first + std::size_t(perColumn * double(j + 1));
        const std::size_t end = j + 1 == count ? last : lowerBoundNear(s, at, last, guess, edge(j + 1));
        out[j].first = at;
        out[j].last = end;
        if (end > at) out[j].range = minMax(channel, at, end);
        at = end;
    }
}

std::pair<std::size_t, std::size_t> SeriesStore::indexRange(std::size_t channel, double from_s, double to_s) const {
    const Samples& s = m_channels.at(channel).samples;
    const std::size_t first = lowerBound(s, 0, s.size(), from_s);
    return {first, upperBound(s, first, s.size(), to_s)};
}

std::vector<Column> SeriesStore::columns(std::size_t channel, double from_s, double to_s, std::size_t count) const {
    std::vector<Column> out(count);
    if (count == 0 || !(from_s <= to_s)) return out;
    const auto [first, last] = indexRange(channel, from_s, to_s);
    const double span = to_s - from_s;
    fillColumns(
        channel, first, last,
        [from_s, span, count](std::size_t j) { return from_s + span * double(j) / double(count); }, out);
    return out;
}

void SeriesStore::gridColumns(std::size_t channel, double width_s, std::int64_t first, std::vector<Column>& out) const {
    if (out.empty()) return;
    const Samples& s = m_channels.at(channel).samples;
    const auto edge = [width_s, first](std::size_t j) { return double(first + std::int64_t(j)) * width_s; };
    const std::size_t from = lowerBound(s, 0, s.size(), edge(0));
    fillColumns(channel, from, lowerBound(s, from, s.size(), edge(out.size())), edge, out);
}

std::size_t SeriesStore::columnPoints(std::size_t channel, const Column& column, Sample* points) const {
    if (column.empty()) return 0;
    const Samples& s = m_channels.at(channel).samples;
    const Sample& head = s[column.first];
    if (column.last - column.first == 1) {
        points[0] = head;
        return 1;
    }
    // The column's vertical stroke ends at the extreme nearer its last sample: the line on to the next
    // column then leaves from about where the signal did, not from a peak it had already left.
    const Sample& tail = s[column.last - 1];
    const bool maximumLast = column.range.maximum - tail.value <= tail.value - column.range.minimum;
    points[0] = {head.time_s, maximumLast ? column.range.minimum : column.range.maximum};
    points[1] = {tail.time_s, maximumLast ? column.range.maximum : column.range.minimum};
    return 2;
}

bool SeriesStore::decimate(std::size_t channel, double from_s, double to_s, std::size_t count,
                           std::vector<Sample>& out) const {
    out.clear();
    const Samples& s = m_channels.at(channel).samples;
    if (count == 0 || s.empty() || !(from_s <= to_s)) return false;
    const auto [first, last] = indexRange(channel, from_s, to_s);
    if (last - first <= 2 * count) { // sparse enough to draw as it is
        out.assign(s.begin() + std::ptrdiff_t(first > 0 ? first - 1 : 0),
                   s.begin() + std::ptrdiff_t(std::min(last + 1, s.size())));
        return false;
    }
    const std::vector<Column> all = columns(channel, from_s, to_s, count);
    if (first > 0) out.push_back(s[first - 1]);
    Sample points[2];
    for (const Column& c : all) out.insert(out.end(), points, points + columnPoints(channel, c, points));
    if (last < s.size()) out.push_back(s[last]);
    return true;
}

} // namespace scope
