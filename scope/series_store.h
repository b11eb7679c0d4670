// Widget-free store of recorded or polled channels (time, value) with units; the plots adapt it to
// QCustomPlot. Appends are incremental; the oldest samples drop when a channel reaches its capacity. A min/max
// pyramid per channel lets a plot draw any time range from O(width) points (decimate), whatever it holds.
#pragma once

#include "min_max_pyramid.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
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

// One pixel column of a channel over a time range: its samples (indices [first, last) into
// Channel::samples) and their min and max value. A column without samples has first == last.
struct Column {
    std::size_t first = 0;
    std::size_t last = 0;
    ValueRange range;
    bool empty() const { return first == last; }
};

class SeriesStore {
public:
    static constexpr std::size_t kDefaultCapacity = 1'000'000; // samples per channel

    explicit SeriesStore(std::size_t capacityPerChannel = kDefaultCapacity) : m_capacity(capacityPerChannel) {}

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
    // Moves on with every change to the samples, and is never the same for two stores (a copy, or what a
    // move leaves behind, starts afresh): a view that drew revision r need not redraw while it is still r.
    std::uint64_t revision() const { return m_revision.value(); }
    // Min and max of the values with time in [from_s, to_s]; nullopt if there are none. O(log n).
    std::optional<ValueRange> valueRange(std::size_t channel, double from_s, double to_s) const;
    // The samples with time in [from_s, to_s]: indices [first, last) into Channel::samples.
    std::pair<std::size_t, std::size_t> indexRange(std::size_t channel, double from_s, double to_s) const;

    // [from_s, to_s] cut into `count` columns of equal width: column j holds the samples with time t where
    //   edge(j) <= t < edge(j + 1),  edge(j) = from_s + (to_s - from_s) * j / count  (in that order of operations),
    // and the last column also t == to_s. Each column's true min and max, in O(count log n) whatever the
    // number of samples. `count` columns, all empty when to_s < from_s.
    std::vector<Column> columns(std::size_t channel, double from_s, double to_s, std::size_t count) const;
    // The columns of a grid anchored at t = 0: column m holds the samples with m * width_s <= t <
    // (m + 1) * width_s (each edge that one product). out.size() columns, from column `first` on. A view can
    // keep these while it pans: the same column always comes out the same.
    void gridColumns(std::size_t channel, double width_s, std::int64_t first, std::vector<Column>& out) const;
    // How a column is drawn: none, its one sample, or its min and max at the times of its first and last
    // sample (the one nearer the last sample's value last). Returns how many points it wrote (<= 2).
    std::size_t columnPoints(std::size_t channel, const Column& column, Sample* points) const;
    // The points that draw the channel over [from_s, to_s] on `count` pixel columns as the raw samples
    // would look there: the samples themselves when there are at most two per column; otherwise, per
    // column with samples, its min and max (at the times of its first and last sample, the one nearer the
    // last sample's value last). Plus the sample just before and just after the range, so the line runs
    // to the plot's edges. Time-ordered; at most 2 count + 2 points. `out` is replaced (its capacity reused).
    // Returns true when the points are per-column min/max pairs, false when they are the samples themselves.
    bool decimate(std::size_t channel, double from_s, double to_s, std::size_t count, std::vector<Sample>& out) const;

private:
    // Min and max of samples [first, last) (first < last): whole leaf blocks from the pyramid, the rest raw.
    ValueRange minMax(std::size_t channel, std::size_t first, std::size_t last) const;
    template <typename Edge>
    void fillColumns(std::size_t channel, std::size_t first, std::size_t last, Edge edge,
                     std::vector<Column>& out) const;

    std::size_t m_capacity;
    std::vector<Channel> m_channels;
    // Each store counts its changes in a range of its own (2^40 of them), drawn when it is made or copied.
    class Revision {
    public:
        Revision() : m_value(fresh()) {}
        Revision(const Revision&) : m_value(fresh()) {}
        Revision(Revision&& other) noexcept : m_value(other.m_value) { other.m_value = fresh(); }
        Revision& operator=(const Revision&) {
            m_value = fresh();
            return *this;
        }
        Revision& operator=(Revision&& other) noexcept {
            m_value = other.m_value;
            other.m_value = fresh();
            return *this;
        }
        void next() { ++m_value; }
        std::uint64_t value() const { return m_value; }

    private:
        static std::uint64_t fresh();
        std::uint64_t m_value;
    };

    std::vector<MinMaxPyramid> m_pyramids; // one per channel; absolute index of samples[0] is dropped()
    Revision m_revision;
};

} // namespace scope
